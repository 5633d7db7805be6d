// Every system's diagram: the arrows drawn are the model's forces at that
// instant (one scale per diagram), and nothing is clipped over the run at
// small and large frame sizes.
#include <catch2/catch.hpp>
#include <cmath>

#include "core/event_trajectory.hpp"
#include "core/models/model.hpp"
#include "core/models/sliding_box_law.hpp"
#include "core/models/vibration_law.hpp"
#include "core/models/road_profile.hpp"
#include "render/draw/canvas.hpp"
#include "scenes/diagrams/bouncing_ball_diagram.hpp"
#include "scenes/diagrams/bumpy_road_diagram.hpp"
#include "scenes/diagrams/diagram_registry.hpp"
#include "scenes/diagrams/elastic_pendulum_diagram.hpp"
#include "scenes/diagrams/orbit_diagram.hpp"
#include "scenes/diagrams/pendulum/pendulum_diagram.hpp"
#include "scenes/diagrams/oscillator_diagram.hpp"
#include "scenes/diagrams/rlc_diagram.hpp"
#include "scenes/diagrams/sliding_box_diagram.hpp"
#include "scenes/diagrams/washing_machine_diagram.hpp"
#include "scenes/overlays/horizontal_layout.hpp"
#include "scenes/scene_factory.hpp"
#include "recorded_diagram.hpp"
#include "test_support.hpp"

using namespace vibra;
using namespace vibra::scenes;
using vibra::test::diagram_as;

namespace {
using Recorded = vibra::test::RecordedDiagram;
Recorded record(const std::string& scene, const std::vector<std::pair<std::string, std::string>>& settings = {}) {
  return vibra::test::record_diagram(scene, settings);
}

/// A built-in scene in layout fbd at w x h, its pre-pass over the run done.
struct RecordedScene {
  SceneConfig config;
  std::unique_ptr<Scene> scene;
  std::vector<std::vector<double>> rows;
  bool follows;  ///< its view follows the body (the road): it runs its ground off the frame on purpose
};

RecordedScene record_scene(const std::string& name, int w, int h) {
  RecordedScene r{load_scene(name), nullptr, {}, false};
  r.config.width = w, r.config.height = h, r.config.layout = Layout::fbd;
  const Parameters p = model_parameters_of(r.config);
  auto run = find_model(r.config.model).build(p);
  r.scene = make_scene(r.config, run->info(), "caption");
  r.rows = vibra::test::rows(*run);
  for (const auto& row : r.rows) r.scene->record(row);
  r.follows = diagram_for(r.config).make({r.config, p, run->info()})->view_at(r.rows[0]).has_value();
  return r;
}
}  // namespace

TEST_CASE("spring-dashpot diagram: arrows are -s(u), -f(u') and F(t) to one scale, from the body's centre line",
          "[scene][diagram]") {
  const Recorded r = record("spring_dashpot");
  auto& d = diagram_as<OscillatorDiagram>(r);
  const VibrationLaw law = VibrationLaw::from(model_parameters_of(r.config));
  const double per = d.force_scale().per_force();
  REQUIRE(per > 0);
  for (const auto& row : r.rows) {
    const auto arrows = d.force_arrows(row);
    REQUIRE(arrows.size() == 3);
    const double forces[] = {-law.spring(row[1]), -law.damper(row[2]), law.external(row[0])};
    for (int i = 0; i < 3; ++i) {
      CHECK(arrows[i].to.x() - arrows[i].from.x() == Approx(per * forces[i]).margin(1e-12));
      CHECK(arrows[i].to.y() == arrows[i].from.y());
      CHECK(arrows[i].from.x() == Approx(d.layout().body_center(row[1]).x()));
    }
  }
  // The longest arrow over the run is the scale's chosen length.
  double longest = 0;
  for (const auto& row : r.rows)
    for (const auto& a : d.force_arrows(row)) longest = std::max(longest, std::abs(a.to.x() - a.from.x()));
  CHECK(longest == Approx(1.1 * d.layout().unit).epsilon(1e-9));
}

TEST_CASE("spring diagram: the wheels roll without slipping, the rim's point on the floor standing still", "[scene][diagram]") {
  // The rim point under the hub at u = 0 is, at u, at the hub (x0 + u, r)
  // plus r (sin turn, -cos turn): to first order in u it must not move.
  const Recorded r = record("spring");
  auto& d = diagram_as<OscillatorDiagram>(r);
  const double radius = d.layout().wheel_radius;
  REQUIRE(radius > 0);
  for (double u : {1e-5, -1e-5, 3e-5}) {
    const double contact_x = u + radius * std::sin(d.wheel_turn(u));
    CHECK(std::abs(contact_x) < 1e-8);
  }
  // A whole turn per 2 pi r travelled, clockwise when moving right.
  CHECK(d.wheel_turn(2 * M_PI * radius) == Approx(-2 * M_PI));
  CHECK(d.wheel_turn(0) == 0);
}

TEST_CASE("the u dimension runs from the equilibrium line to the body's centre line, above the body, on wheels or not",
          "[scene][diagram]") {
  for (bool wheels : {true, false}) {
    const HorizontalLayout l(0.8, wheels);
    for (double u : {0.8, 0.3, -0.55, 0.0}) {
      INFO("wheels " << wheels << ", u = " << u);
      const auto [rest, body] = l.u_dimension(u);
      CHECK(rest.x() == l.equilibrium_x());
      CHECK(body.x() == Approx(l.body_center(u).x()));
      CHECK(body.x() - rest.x() == Approx(u).margin(1e-15));
      CHECK(rest.y() == body.y());
      CHECK(rest.y() > l.body_bottom() + l.body_height);  // above the body
    }
  }
}

TEST_CASE("spring diagram without damping or forcing draws the spring force alone", "[scene][diagram]") {
  const Recorded r = record("spring");
  auto& d = diagram_as<OscillatorDiagram>(r);
  for (const auto& row : r.rows) CHECK(d.force_arrows(row).size() == 1);
}

TEST_CASE("sliding box diagram: the friction arrow is kinetic while sliding, static at rest", "[scene][diagram]") {
  const Recorded r = record("sliding_box", {{"mu", "0.2"}});
  auto& d = diagram_as<SlidingBoxDiagram>(r);
  SlidingBoxLaw law;
  law.mu = 0.2;
  bool saw_rest = false;
  for (const auto& row : r.rows) {
    Arrow spring{}, friction{};
    for (const DrawnForce& f : d.forces(row)) {
      if (f.kind == ForceKind::spring) spring = f.arrow;
      if (f.kind == ForceKind::friction) friction = f.arrow;
    }
    const double per = (spring.to.x() - spring.from.x()) / -law.spring(row[1]);
    const double pull = friction.to.x() - friction.from.x();
    const double m = d.friction_magnification();
    if (row[2] != 0) CHECK(pull == Approx(-0.2 * (row[2] > 0 ? 1 : -1) * per * m).epsilon(1e-9));
    if (row[2] == 0 && row[0] > 1) {
      saw_rest = true;
      // Static friction balances the spring: the two arrows are opposite, equal but for the magnification.
      CHECK(pull == Approx(-m * (spring.to.x() - spring.from.x())).margin(1e-12));
    }
  }
  CHECK(saw_rest);
  CHECK(d.friction_magnification() == 2);  // mu = 0.2 against a largest spring force 1: x2 makes it 40%
}

TEST_CASE("washing machine diagram: the drum's mass at the forcing's phase, arrows -u, -beta u', sin(gamma t)",
          "[scene][diagram]") {
  const Recorded r = record("washing_machine");
  auto& d = diagram_as<WashingMachineDiagram>(r);
  const double gamma = 1.1, beta = 0.05;
  for (size_t i = 0; i < r.rows.size(); i += 7) {
    const auto& row = r.rows[i];
    const Point m = d.drum_mass_offset(row[0]);
    CHECK(std::atan2(m.y(), m.x()) == Approx(std::remainder(gamma * row[0], 2 * M_PI)).margin(1e-9));
    const auto arrows = d.force_arrows(row);
    REQUIRE(arrows.size() == 3);
    const double per = (arrows[2].to.y() - arrows[2].from.y()) / std::sin(gamma * row[0]);
    if (std::abs(std::sin(gamma * row[0])) > 0.1) {
      CHECK(arrows[0].to.y() - arrows[0].from.y() == Approx(-row[1] * per).epsilon(1e-9));
      CHECK(arrows[1].to.y() - arrows[1].from.y() == Approx(-beta * row[2] * per).epsilon(1e-9).margin(1e-12));
    }
  }
}

TEST_CASE("washing machine's u panel: the steady amplitude's lines at +A and -A, the forcing panel sin(gamma t)",
          "[scene][diagram][panels]") {
  // u'' + beta u' + u = sin(gamma t) settles to amplitude A = 1/sqrt((1 - gamma^2)^2 + (beta gamma)^2).
  const Recorded r = record("washing_machine");
  const double gamma = 1.1, beta = 0.05;
  const double A = 1 / std::sqrt(std::pow(1 - gamma * gamma, 2) + std::pow(beta * gamma, 2));
  const std::vector<PanelSpec> panels = diagram_as<WashingMachineDiagram>(r).panels();
  REQUIRE(panels.size() == 2);
  const auto& u = panels[0].series;
  REQUIRE(u.size() == 4);  // numerical, exact, then the two lines
  const std::vector<double> row = r.rows.at(r.rows.size() / 2);
  CHECK(u[0].value(row) == row[1]);
  CHECK(u[2].label == "±steady amplitude");
  CHECK(u[2].value(row) == Approx(A).epsilon(1e-12));
  CHECK(u[3].value(row) == Approx(-A).epsilon(1e-12));
  CHECK(u[3].label.empty());  // one legend entry for the pair
  REQUIRE(panels[1].series.size() == 1);
  CHECK(panels[1].series[0].value(row) == Approx(std::sin(gamma * row[0])).margin(1e-12));
}

TEST_CASE("bumpy road diagram: the wheel on the road, the body at L + u over the axle, arrows -k u and -b u'",
          "[scene][diagram]") {
  const Recorded r = record("bumpy_road", {{"exaggerate", "1"}});
  auto& d = diagram_as<BumpyRoadDiagram>(r);
  const Parameters p = model_parameters_of(r.config);
  const double R = p.number("R"), L = p.number("L"), k = p.number("k"), b = p.number("b");
  CHECK(d.exaggeration() == 1);
  CHECK(d.force_key()->note.empty());
  // Spring and damper stand outside the wheel: neither crosses its rim.
  CHECK(d.strut_offset() - 0.45 * R / 2 > R);
  for (size_t i = 0; i < r.rows.size(); i += 5) {
    const auto& row = r.rows[i];
    CHECK(d.axle(row).y() == Approx(row[4] + R));
    CHECK(d.body_bottom(row) == Approx(row[4] + R + L + row[1]));
    const auto forces = d.forces(row);
    REQUIRE(forces.size() == 2);
    const Arrow& s = forces[0].arrow;
    const Arrow& f = forces[1].arrow;
    const double spring = s.to.y() - s.from.y(), damper = f.to.y() - f.from.y();
    if (std::abs(row[1]) > 1e-3 && std::abs(row[2]) > 1e-2) CHECK(damper / spring == Approx((b * row[2]) / (k * row[1])).epsilon(1e-9));
    // Both vertical, as the forces are: the spring's left of the body's
    // centre line, the damper's right of it, as the struts stand.
    CHECK(s.to.x() == s.from.x());
    CHECK(f.to.x() == f.from.x());
    CHECK(s.from.x() < row[3]);
    CHECK(f.from.x() > row[3]);
    // The view follows the vehicle.
    const auto view = d.view_at(row);
    REQUIRE(view);
    CHECK(view->centre.x() == row[3]);
  }
}

TEST_CASE("bumpy road diagram: the following view moves only sideways, its zoom and rows the same to the last bit",
          "[scene][diagram]") {
  // A view whose size came from a moving box's corners varied in its last
  // bits from frame to frame, and the road's tiles were drawn again for each
  // (three of every four frames of the default road at 720p).
  const Recorded r = record("bumpy_road", {});
  const auto& d = diagram_as<BumpyRoadDiagram>(r);
  // Narrow for the view's width, so the zoom is the width's (as in the scene at 720p).
  const render::PixelRect area{40, 30, 300, 600};
  std::optional<render::WorldView> first;
  size_t moved = 0;
  for (const auto& row : r.rows) {
    const auto following = d.view_at(row);
    REQUIRE(following);
    const render::WorldView view(following->centre, following->sizes, area);
    if (!first) first = view;
    CHECK(view.zoom() == first->zoom());
    CHECK(view.to_pixel(Point(0, 0)).y() == first->to_pixel(Point(0, 0)).y());
    CHECK(view.to_pixel(Point(row[3], 0)).x() == Approx(area.x + 0.5 * area.w).margin(1e-9));
    moved += view.to_pixel(Point(0, 0)).x() != first->to_pixel(Point(0, 0)).x();
  }
  CHECK(moved > r.rows.size() / 2);  // the car drove: the view did follow
}

TEST_CASE("bumpy road diagram: the view holds the body over the highest bump with room for its arrows above",
          "[scene][diagram]") {
  // The body's top is F (h + u) + R + L + 0.9 R; above it at least 0.4 R
  // for the arrows; below, the road under the wheel.
  using Settings = std::vector<std::pair<std::string, std::string>>;
  const std::vector<Settings> cases = {{{"exaggerate", "1"}}, {{"exaggerate", "4"}}, {},  // automatic
                                       {{"road", "sine"}, {"A", "0.8"}, {"k", "6e6"}, {"b", "6000"}, {"exaggerate", "1"}}};  // stiff, over bumps taller than the wheel
  for (const Settings& settings : cases) {
    INFO((settings.empty() ? "automatic" : settings.back().first + "=" + settings.back().second) << ", " << settings.size() << " keys");
    const Recorded r = record("bumpy_road", settings);
    auto& d = diagram_as<BumpyRoadDiagram>(r);
    const double R = model_parameters_of(r.config).number("R"), F = d.exaggeration();
    double road_span = 0;
    for (const auto& row : r.rows) {
      const auto view = d.view_at(row);
      REQUIRE(view);
      CHECK(view->box().max().y() - (d.body_bottom(row) + 0.9 * R) >= 0.4 * R - 1e-12);
      CHECK(view->box().min().y() < F * row[4]);
      road_span = std::max(road_span, std::abs(row[4]));
    }
    CHECK(F * road_span > 0.1 * R);  // the bumps are tall enough to matter
  }
}

TEST_CASE("bumpy road diagram: the wheel rolls without slipping, clockwise as the vehicle drives right", "[scene][diagram]") {
  // The rim point under the hub at x = 0 is, at x, at the hub plus
  // R (sin turn, -cos turn): to first order in x it must not move.
  const Recorded r = record("bumpy_road");
  auto& d = diagram_as<BumpyRoadDiagram>(r);
  const double R = model_parameters_of(r.config).number("R");
  REQUIRE(R > 0);
  for (double x : {1e-5, -1e-5, 3e-5}) CHECK(std::abs(x + R * std::sin(d.wheel_turn(x))) < 1e-8);
  CHECK(d.wheel_turn(2 * M_PI * R) == Approx(-2 * M_PI));
}

TEST_CASE("bumpy road diagram: heights drawn F times larger, F chosen so that the motion shows and stays a vehicle",
          "[scene][diagram]") {
  // exaggerate = 4: the road and the body's u four times taller, R and L true, and the key says so.
  const Recorded r = record("bumpy_road", {{"exaggerate", "4"}});
  auto& d = diagram_as<BumpyRoadDiagram>(r);
  const Parameters p = model_parameters_of(r.config);
  const double R = p.number("R"), L = p.number("L");
  CHECK(d.exaggeration() == 4);
  CHECK(d.force_key()->note == "heights drawn ×4");
  for (size_t i = 0; i < r.rows.size(); i += 7) {
    CHECK(d.axle(r.rows[i]).y() == Approx(4 * r.rows[i][4] + R));
    CHECK(d.body_bottom(r.rows[i]) - d.axle(r.rows[i]).y() == Approx(L + 4 * r.rows[i][1]));
  }
  // Automatic: the largest of 1, 2, 3, 4, 5 x 10^k keeping the swing within L/2 and the bumps within 0.8 R.
  const BumpyRoadDiagram::Vehicle v{6e4, 600, 0.3, 0.6};
  CHECK(BumpyRoadDiagram::automatic_exaggeration(0.08, 0.06, v) == 3);       // 3.75 and 4 allowed
  CHECK(BumpyRoadDiagram::automatic_exaggeration(1e-4, 1e-4, v) == 2000);    // 0.24 / 1e-4 = 2400
  CHECK(BumpyRoadDiagram::automatic_exaggeration(0.01, 1e-4, v) == 30);      // the swing binds: 0.3 / 0.01 = 30
  CHECK(BumpyRoadDiagram::automatic_exaggeration(0.1, 0.01, v) == 1);        // a swing of L/6 shows already
  CHECK(BumpyRoadDiagram::automatic_exaggeration(0, 0, v) == 1);             // nothing moves
  const Recorded automatic = record("bumpy_road");
  auto& a = diagram_as<BumpyRoadDiagram>(automatic);
  double swing = 0;
  for (const auto& row : automatic.rows) swing = std::max(swing, std::abs(row[1]));
  CHECK(a.exaggeration() > 1);
  CHECK(a.exaggeration() * swing <= 0.5 * L);
  CHECK(a.exaggeration() * swing > L / 7);  // now it shows
}

TEST_CASE("bouncing ball diagram: the ball on the ground at h, v to one scale, the weight down, impacts as the model's",
          "[scene][diagram]") {
  const Recorded r = record("bouncing_ball");
  auto& d = diagram_as<BouncingBallDiagram>(r);
  // The impacts the diagram marks are the ones the model finds.
  auto run = find_model("bouncing-ball").build(model_parameters_of(r.config));
  std::vector<double> impacts;
  dynamic_cast<EventTrajectory&>(*run).on_event([&](const EventTrajectory::Event& e) { impacts.push_back(e.t); });
  while (run->advance()) {
  }
  REQUIRE(d.impacts().size() == impacts.size());
  for (size_t i = 0; i < impacts.size(); ++i) CHECK(d.impacts()[i] == Approx(impacts[i]).epsilon(1e-9));
  double per_speed = 0, longest = 0, highest = 0;
  for (const auto& row : r.rows) {
    highest = std::max(highest, row[1]);
    CHECK(d.ball_center(row).y() - d.radius() == Approx(row[1]).margin(1e-15));
    const auto v = d.velocity_arrow(row);
    const Arrow w = d.forces(row).front().arrow;
    CHECK(v.to.x() == v.from.x());
    // Beside the ball, 2.2 radii right of its centre: clear of it by 1.2 radii.
    CHECK(v.from.x() == Approx(d.ball_center(row).x() + 2.2 * d.radius()));
    if (std::abs(row[2]) > 0.1) {
      if (per_speed == 0) per_speed = (v.to.y() - v.from.y()) / row[2];
      CHECK((v.to.y() - v.from.y()) / row[2] == Approx(per_speed).epsilon(1e-12));
    }
    longest = std::max(longest, std::abs(v.to.y() - v.from.y()));
    // Gravity points down, ending at the ball's bottom: on the ground, never in it.
    CHECK(w.to.y() < w.from.y());
    CHECK(w.to.y() == Approx(row[1]).margin(1e-12));
  }
  CHECK(per_speed > 0);
  CHECK(longest == Approx(0.42 * highest).epsilon(1e-9));
  // The view: the ball's column in the middle (0.75 of the height to each
  // side, for the labels and the tally), the hatching under the ground.
  CHECK(r.world.min().x() == Approx(-0.75 * highest));
  CHECK(r.world.max().x() == Approx(0.75 * highest));
  CHECK(r.world.min().y() == Approx(-0.12 * highest));
}

TEST_CASE("rlc diagram: the current's arrow follows I, the plates' signs follow q", "[scene][diagram]") {
  const Recorded r = record("rlc", {{"R", "0.3"}});
  auto& d = diagram_as<RlcDiagram>(r);
  double largest_I = 0, largest_q = 0;
  for (const auto& row : r.rows) largest_I = std::max(largest_I, std::abs(row[2])), largest_q = std::max(largest_q, std::abs(row[1]));
  for (const auto& row : r.rows) {
    // Clockwise for I > 0: left to right along the top wire, at the loop's middle.
    const auto a = d.current_arrow(row);
    CHECK(a.to.y() == a.from.y());
    CHECK(a.to.x() - a.from.x() == Approx(RlcDiagram::kLongestCurrent * row[2] / largest_I).margin(1e-12));
    CHECK(0.5 * (a.from.x() + a.to.x()) == Approx(2));
    // I > 0 charges the right plate (the one nearer `to`): it is positive when q > 0.
    const auto c = d.capacitor(row);
    CHECK(c.sign_of_to_plate == (row[1] > 0 ? 1 : row[1] < 0 ? -1 : 0));
    CHECK(c.marks == std::lround(5 * std::abs(row[1]) / largest_q));
    CHECK(c.plate_from[1].x() > c.plate_from[0].x());
  }
}

TEST_CASE("elastic pendulum diagram: mg, the wire's force (L - beta)/(1 - beta) toward the pivot and the drag, one scale",
          "[scene][diagram]") {
  const double beta = 0.9, gamma = 0.05;
  const Recorded r = record("elastic_pendulum", {{"gamma", "0.05"}});
  auto& d = diagram_as<ElasticPendulumDiagram>(r);
  const double per = d.force_scale().per_force();
  REQUIRE(per > 0);
  for (const auto& row : r.rows) {
    const Point p(row[1], row[2]), v(row[3], row[4]), pivot(0, 1);
    const double L = (p - pivot).norm();
    const auto a = d.force_arrows(row);
    CHECK((a[0].to - a[0].from - Point(0, -per)).norm() < 1e-12);
    const Point wire = per * (L - beta) / (1 - beta) * (pivot - p) / L;
    CHECK((a[1].to - a[1].from - wire).norm() < 1e-12);
    const Point drag = -per * gamma / (beta * beta) * v.norm() * v;
    CHECK((a[2].to - a[2].from - drag).norm() < 1e-12);
    for (const auto& arrow : a) CHECK((arrow.from - p).norm() == 0);
  }
  // The trail passes through every row's position within its spacing.
  const auto& trail = d.trail().points();
  REQUIRE(trail.size() > 10);
  CHECK(trail.front().p.x() == Approx(r.rows.front()[1]));
}

TEST_CASE("pendulum diagram: the largest pull of the wire is drawn as long as its room inside the wire, mg in proportion",
          "[scene][diagram]") {
  // Theta = 60 degrees, no drag: S = omega^2 + cos(theta) peaks at the
  // bottom at 1 + 2 (1 - cos 60) = 2, which points inward, where it has
  // kInwardRoom; every other force (mg = 1) gets kArrowRoom.
  const Recorded r = record("pendulum", {{"Theta", "60"}, {"alpha", "0"}, {"steps_per_period", "400"}});
  auto& d = diagram_as<PendulumDiagram>(r);
  double S_max = 0;
  for (const auto& row : r.rows) S_max = std::max(S_max, row[3]);
  CHECK(S_max == Approx(2).epsilon(1e-4));
  const double inward = PendulumDiagram::kInwardRoom, room = PendulumDiagram::kArrowRoom;
  REQUIRE(S_max * room / inward > 1);  // S, not mg, sets the scale
  CHECK(d.force_scale().per_force() == Approx(inward / S_max).epsilon(1e-12));
  CHECK(d.force_scale().length(1) < room);  // mg drawn in proportion, unclipped
}

TEST_CASE("elastic pendulum diagram's panels: theta in degrees from the wire's direction, S/mg from its stretch",
          "[scene][diagram]") {
  const double beta = 0.9;
  const Recorded r = record("elastic_pendulum", {{"Theta", "40"}});
  const auto panels = diagram_as<ElasticPendulumDiagram>(r).panels();
  REQUIRE(panels.size() == 2);
  CHECK_THAT(panels[0].label, Catch::Contains("degrees"));
  double widest = 0;
  for (const auto& row : r.rows) {
    // theta from the bob's place below the pivot (0, 1): atan2(x, 1 - y).
    const double theta = std::atan2(row[1], 1 - row[2]) * 180 / M_PI;
    CHECK(panels[0].series[0].value(row) == Approx(theta).margin(1e-9));
    const double L = std::hypot(row[1], row[2] - 1);
    CHECK(panels[1].series[0].value(row) == Approx((L - beta) / (1 - beta)).margin(1e-9));
    widest = std::max(widest, std::abs(theta));
  }
  CHECK(widest > 30);  // the swing is in degrees, not radians
}

TEST_CASE("orbit diagram: gravity -x/|x|^3 and v to their scales, and the circular orbit keeps radius 1",
          "[scene][diagram]") {
  const Recorded r = record("orbit");
  auto& d = diagram_as<OrbitDiagram>(r);
  CHECK(d.circle_radius() == 1);
  Point gravity_per(0, 0), speed_per(0, 0);
  for (const auto& row : r.rows) {
    const Point x(row[1], row[2]), v(row[3], row[4]);
    const auto a = d.arrows(row);
    const Point g = -x / std::pow(x.norm(), 3);
    // Parallel to the force and the velocity, with one length per unit over the run.
    CHECK(std::abs((a[0].to - a[0].from).x() * g.y() - (a[0].to - a[0].from).y() * g.x()) < 1e-12);
    CHECK((a[0].to - a[0].from).dot(g) > 0);
    CHECK((a[0].to - a[0].from).norm() / g.norm() == Approx(0.45 / 1).epsilon(1e-6));
    CHECK((a[1].to - a[1].from).norm() / v.norm() == Approx(0.45).epsilon(1e-6));
    CHECK((a[1].to - a[1].from).dot(v) > 0);
  }
  for (const auto& p : d.trail().points()) CHECK(p.p.norm() == Approx(1).epsilon(1e-7));
}

TEST_CASE("orbit diagram: on an eccentric orbit gravity's arrow shrinks as 1/r^2 at one scale, and circles of any radius are drawn",
          "[scene][diagram]") {
  // From x0 = 1 at 1.2 times the circular speed: out to r = 1.44/0.56.
  const Recorded r = record("orbit", {{"vy0", "1.2"}, {"periods", "3"}});
  auto& d = diagram_as<OrbitDiagram>(r);
  CHECK(d.circle_radius() == 0);  // not circular: no circle to compare with
  double g_largest = 0, v_largest = 0, r_min = 1e300, r_max = 0;
  for (const auto& row : r.rows) {
    const Point x(row[1], row[2]), v(row[3], row[4]);
    g_largest = std::max(g_largest, 1 / x.squaredNorm()), v_largest = std::max(v_largest, v.norm());
    r_min = std::min(r_min, x.norm()), r_max = std::max(r_max, x.norm());
  }
  CHECK(r_max / r_min > 2.5);
  for (const auto& row : r.rows) {
    const Point x(row[1], row[2]), v(row[3], row[4]);
    const auto a = d.arrows(row);
    // The longest arrow 0.45 world units, every other in proportion to its force.
    CHECK((a[0].to - a[0].from - 0.45 / g_largest * (-x / std::pow(x.norm(), 3))).norm() < 1e-9);
    CHECK((a[1].to - a[1].from - 0.45 / v_largest * v).norm() < 1e-9);
  }
  // A circular start at r = 2 (speed 1/sqrt(2)) gets its circle, of radius 2.
  const Recorded wide = record("orbit", {{"x0", "2"}, {"vy0", "0.70710678118654752"}});
  CHECK(diagram_as<OrbitDiagram>(wide).circle_radius() == 2);
}

TEST_CASE("orbit diagram: Euler-Cromer's drift shows in the trail after 100 orbits, PEFRL's does not",
          "[scene][diagram]") {
  auto drift = [](const std::string& scheme) {
    const Recorded r = record("orbit", {{"scheme", scheme}, {"periods", "100"}, {"steps_per_period", "200"}});
    double worst = 0;
    for (const auto& p : diagram_as<OrbitDiagram>(r).trail().points()) worst = std::max(worst, std::abs(p.p.norm() - 1));
    return worst;
  };
  const double euler_cromer = drift("euler-cromer"), pefrl = drift("pefrl");
  CHECK(euler_cromer > 1e-2);
  CHECK(pefrl < 1e-6);
}

TEST_CASE("orbit diagram: --window keeps the last orbits of the trail", "[scene][diagram]") {
  const Recorded r = record("orbit", {{"window", "1periods"}, {"periods", "3"}});
  auto& d = diagram_as<OrbitDiagram>(r);
  CHECK(d.window() == Approx(2 * M_PI));
  CHECK(diagram_as<OrbitDiagram>(record("orbit")).window() == 0);
  // One orbit's worth of trail at the end: the points of the last 2 pi.
  const auto last = d.trail().between(6 * M_PI - 2 * M_PI, 6 * M_PI);
  CHECK(last.size() > 100);
  CHECK(last.size() < d.trail().points().size() / 2);
}

TEST_CASE("nothing is clipped: over the run no drawing touches the frame's edge, small or large", "[heavy][scene][diagram]") {
  for (const std::string& name : builtin_scene_names()) {
    for (auto [w, h] : {std::pair{640, 360}, std::pair{1920, 1080}}) {
      const auto [config, scene, rows, follows] = record_scene(name, w, h);
      render::Canvas canvas = render::Canvas::image(w, h);
      canvas.track_damage();
      const size_t every = std::max<size_t>(1, rows.size() / 60);
      for (size_t i = 0; i < rows.size(); i += every) {
        canvas.begin_frame();
        scene->draw(canvas, rows[i]);
        INFO(name << " at " << w << "x" << h << ", t = " << rows[i][0]);
        REQUIRE_FALSE(canvas.drawn().all());
        for (const auto& rect : canvas.drawn().rects()) {
          CHECK(rect.y0 > 0);
          if (follows) continue;
          CHECK(rect.x0 > 0);
          CHECK(rect.x1 < w);
          CHECK(rect.y1 < h);
        }
      }
    }
  }
}

namespace {
/// Whether pixel (x, y) of a frame is the background, near enough (antialiasing).
bool blank(const render::Canvas& canvas, int x, int y, const render::Color& background) {
  const auto* p = canvas.data() + y * canvas.stride() + 4 * x;  // BGRA
  return std::abs(p[2] - background.r * 255) < 40 && std::abs(p[1] - background.g * 255) < 40 &&
         std::abs(p[0] - background.b * 255) < 40;
}

/// The longest run of drawn pixels in pixel row `y`, as [first, last] columns.
std::pair<int, int> longest_drawn_run(const render::Canvas& canvas, int y, const render::Color& background) {
  std::pair<int, int> best{0, -1};
  for (int x = 0, start = -1; x <= canvas.width(); ++x) {
    if (x < canvas.width() && !blank(canvas, x, y, background)) {
      if (start < 0) start = x;
    } else if (start >= 0) {
      if (x - 1 - start > best.second - best.first) best = {start, x - 1};
      start = -1;
    }
  }
  return best;
}
}  // namespace

TEST_CASE("layout fbd centres every diagram: the pendulums' pivots on the centre line, the rest over the run",
          "[heavy][scene][diagram]") {
  const int w = 1280, h = 720;
  for (const std::string& name : builtin_scene_names()) {
    const auto [config, scene, rows, follows] = record_scene(name, w, h);
    if (follows) continue;
    render::Canvas canvas = render::Canvas::image(w, h);
    if (config.model == "pendulum" || config.model == "elastic-pendulum") {
      // A pendulum hangs from the frame's centre line, whichever side it
      // swings further to: its ceiling, the longest line near the top, is
      // centred.
      scene->draw(canvas, rows.back());
      canvas.flush();
      std::pair<int, int> ceiling{0, -1};
      for (int y = 60; y < h / 3; ++y) {
        const auto run_at_y = longest_drawn_run(canvas, y, config.colors.background);
        if (run_at_y.second - run_at_y.first > ceiling.second - ceiling.first) ceiling = run_at_y;
      }
      INFO(name << ": ceiling from x = " << ceiling.first << " to " << ceiling.second << " of " << w);
      CHECK(ceiling.second - ceiling.first > 50);
      CHECK(std::abs((ceiling.first + ceiling.second) / 2.0 - (w - 1) / 2.0) <= 2);
      continue;
    }
    // Any other drawing's extent over the run (below the read-out, above the
    // force key and the caption) is centred: its left and right margins
    // differ by under 3% of w.
    int left = w, right = -1;
    const size_t every = std::max<size_t>(1, rows.size() / 40);
    for (size_t i = 0; i < rows.size(); i += every) {
      scene->draw(canvas, rows[i]);
      canvas.flush();
      for (int y = 60; y < h - 110; y += 2)
        for (int x = 0; x < w; ++x)
          if (!blank(canvas, x, y, config.colors.background)) left = std::min(left, x), right = std::max(right, x);
    }
    INFO(name << ": drawn from x = " << left << " to " << right << " of " << w);
    REQUIRE(right > left);
    CHECK(std::abs(left - (w - 1 - right)) < 0.03 * w);
  }
}

TEST_CASE("the force key's names are in the colours the arrows are drawn in", "[scene][diagram]") {
  using Colours = std::vector<vibra::render::Color>;
  auto check = [](const std::string& scene, auto pick) {
    const Recorded r = record(scene);
    Colours names;
    const auto key = r.diagram->force_key();  // kept: its names are read below
    REQUIRE(key);
    for (const auto& n : key->names) names.push_back(n.color);
    CHECK(names == pick(r.config.colors));
  };
  using C = const vibra::scenes::SceneColors&;
  check("pendulum", [](C c) { return Colours{c.gravity, c.wire_force, c.drag}; });
  check("spring_dashpot", [](C c) { return Colours{c.gravity, c.drag, c.wire_force}; });
  check("sliding_box", [](C c) { return Colours{c.gravity, c.drag, c.wire_force}; });
  check("bumpy_road", [](C c) { return Colours{c.gravity, c.drag}; });
}

TEST_CASE("every diagram notes where it draws, so a comparison paints its ghosts' layer only there",
          "[scene][diagram][comparison]") {
  // The ghosts are drawn into a group as large as the diagram's part and
  // painted faint only inside the box the canvas noted while they drew: a
  // pixel drawn outside that box would be lost from the frame.
  for (const std::string& name : builtin_scene_names()) {
    Recorded r = record(name);
    for (const bool ghost : {false, true}) {
      r.diagram->set_ghost(ghost);
      for (const double moment : {0.0, 0.37, 0.81, 1.0}) {
        INFO(name << (ghost ? ", as a ghost" : "") << ", at " << moment << " of the run");
        const auto& row = r.rows[size_t(std::llround(moment * double(r.rows.size() - 1)))];
        render::Canvas canvas = render::Canvas::image(640, 360);
        canvas.clear(render::palette::paper);
        const std::optional<FollowingView> moving = r.diagram->view_at(row);  // the road's view follows the car
        const render::PixelRect area{40, 30, 560, 300};
        const render::WorldView view = moving ? render::WorldView(moving->centre, moving->sizes, area)
                                              : render::WorldView(r.world, area);
        Eigen::AlignedBox2d noted;
        canvas.extent_into(&noted);
        r.diagram->draw(canvas, view, row);
        canvas.extent_into(nullptr);
        canvas.flush();
        const std::uint32_t paper = *reinterpret_cast<const std::uint32_t*>(canvas.data());
        long long drawn = 0, outside = 0;
        for (int y = 0; y < canvas.height(); ++y)
          for (int x = 0; x < canvas.width(); ++x) {
            if (reinterpret_cast<const std::uint32_t*>(canvas.data() + y * canvas.stride())[x] == paper) continue;
            ++drawn;
            // A pixel is touched by what covers any part of it.
            if (x + 1 <= noted.min().x() || x >= noted.max().x() || y + 1 <= noted.min().y() || y >= noted.max().y())
              ++outside;
          }
        CHECK(drawn > 50);
        CHECK(outside == 0);
      }
    }
  }
}
