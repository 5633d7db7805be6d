// Free-body diagrams complete and correct in every state: the forces drawn at rest, in flight, sliding and stuck
// are the model's (section 1.12.3, 1.12.9), no arrow passes through the ground or a wall, and keys list exactly them.
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <tuple>

#include "core/models/model.hpp"
#include "core/models/sliding_box_law.hpp"
#include "render/draw/canvas.hpp"
#include "render/labels/drawing_record.hpp"
#include "scenes/diagrams/bouncing_ball_diagram.hpp"
#include "scenes/diagrams/bumpy_road_diagram.hpp"
#include "scenes/diagrams/comparison_diagram.hpp"
#include "scenes/diagrams/diagram_registry.hpp"
#include "scenes/diagrams/oscillator_diagram.hpp"
#include "scenes/diagrams/sliding_box_diagram.hpp"
#include "scenes/scene_factory.hpp"
#include "recorded_diagram.hpp"

using namespace vibra;
using namespace vibra::scenes;
using vibra::test::diagram_as;
using Settings = std::vector<std::pair<std::string, std::string>>;

namespace {
using Run = vibra::test::RecordedDiagram;
Run run_of(const std::string& scene, const Settings& settings = {}) { return vibra::test::record_diagram(scene, settings); }

std::vector<ForceKind> kinds(const std::vector<DrawnForce>& forces) {
  std::vector<ForceKind> out;
  for (const DrawnForce& f : forces) out.push_back(f.kind);
  return out;
}

/// The key's names without markup: "<i>mg</i> weight" -> "mg weight".
std::vector<std::string> key_names(const Diagram& d) {
  std::vector<std::string> out;
  const auto key = d.force_key();
  REQUIRE(key);
  for (const ForceName& n : key->names) {
    std::string plain;
    bool tag = false;
    for (char c : n.name) {
      if (c == '<') tag = true;
      else if (c == '>') tag = false;
      else if (!tag) plain += c;
    }
    out.push_back(plain);
  }
  return out;
}

/// The labels a diagram asks for when it draws `row` (what the frame shows).
std::vector<std::string> drawn_labels(Diagram& d, const WorldBox& world, std::span<const double> row) {
  render::Canvas canvas = render::Canvas::image(640, 360);
  render::DrawingRecord record;
  canvas.record_into(&record);
  d.draw(canvas, render::WorldView(world, {40, 30, 560, 300}), row);
  canvas.record_into(nullptr);
  std::vector<std::string> out;
  for (const auto& l : record.labels) out.push_back(l.markup);
  return out;
}

/// The ball of the scene bouncing_ball: when it comes to rest. The n-th
/// rebound leaves at C_R^n sqrt(2 g h0) and flies 2 C_R^n sqrt(2 g h0)/g; it
/// rests at the first rebound slower than eps_v (section 1.12.9).
double rest_time(double h0, double g, double C_R, double eps_v) {
  double t = std::sqrt(2 * h0 / g), speed = std::sqrt(2 * g * h0);
  for (int n = 1; n < 1000; ++n) {
    speed *= C_R;
    if (speed < eps_v) return t;
    t += 2 * speed / g;
  }
  return INFINITY;
}

/// The box released from rest at u = 1 (linear spring): half swings of
/// length pi, the amplitude shrinking by 2 mu each, stuck at the first
/// turning point with |u| <= mu (section 1.12.3, docs/models.md).
struct Sticking {
  double t, u;
};
Sticking sticking(double mu) {
  double a = 1;
  for (int n = 0; n < 10000; ++n) {
    if (std::abs(a) <= mu) return {n * M_PI, a};
    a = (a > 0 ? 2 * mu : -2 * mu) - a;
  }
  return {INFINITY, 0};
}
}  // namespace

TEST_CASE("bouncing ball: mg in flight, at rest on the ground N = mg up from it, and the key lists N only "
          "for a run that rests",
          "[scene][diagram][free-body]") {
  const Run r = run_of("bouncing_ball");
  auto& d = diagram_as<BouncingBallDiagram>(r);
  const Parameters p = model_parameters_of(r.config);
  const double rest = rest_time(p.number("h0"), p.number("g"), p.number("C_R"), p.number("eps_v"));
  REQUIRE(rest < r.rows.back()[0] - 0.1);  // the scene's run ends at rest
  int resting = 0, flying = 0;
  for (const auto& row : r.rows) {
    if (std::abs(row[0] - rest) < 1e-6) continue;
    const auto forces = d.forces(row);
    const Arrow& w = forces.front().arrow;
    REQUIRE(forces.front().kind == ForceKind::weight);
    CHECK(w.to.x() == w.from.x());
    CHECK(w.to.y() < w.from.y());  // down
    if (row[0] > rest) {
      ++resting;
      REQUIRE(kinds(forces) == std::vector{ForceKind::weight, ForceKind::normal});
      const Arrow& n = forces[1].arrow;
      // Up from the ground, where the ball touches it, beside the ball opposite mg; as long as mg: N = mg.
      CHECK(n.from.y() == 0);
      CHECK(n.from.x() == Approx(-w.from.x()).epsilon(1e-12));
      CHECK(n.to.x() == n.from.x());
      CHECK(n.to.y() - n.from.y() == Approx(w.from.y() - w.to.y()).epsilon(1e-12));
    } else {
      ++flying;
      CHECK(kinds(forces) == std::vector{ForceKind::weight});
    }
  }
  CHECK(resting > 5);
  CHECK(flying > 50);
  CHECK(key_names(d) == std::vector<std::string>{"mg weight", "N ground, at rest"});
  // Two periods end long before the rest: no N, in the drawing or the key.
  const Run short_run = run_of("bouncing_ball", {{"periods", "2"}});
  REQUIRE(short_run.rows.back()[0] < rest);
  CHECK(key_names(*short_run.diagram) == std::vector<std::string>{"mg weight"});
}

TEST_CASE("bouncing ball: each arrow's label sits on the arrow's side away from the ball, so mg's and v's never meet",
          "[scene][diagram][free-body]") {
  const Run r = run_of("bouncing_ball");
  auto& d = diagram_as<BouncingBallDiagram>(r);
  const render::WorldView view(r.world, {40, 30, 560, 300});
  int labels = 0;
  for (size_t i = 0; i < r.rows.size(); i += 7) {
    const auto& row = r.rows[i];
    render::Canvas canvas = render::Canvas::image(640, 360);
    render::DrawingRecord record;
    canvas.record_into(&record);
    d.draw(canvas, view, row);
    canvas.record_into(nullptr);
    const double ball_x = view.to_pixel(d.ball_center(row)).x();
    for (const auto& l : record.labels) {
      if (l.markup.find("impact") != std::string::npos) continue;  // the tally, not an arrow's
      INFO("t = " << row[0] << ", label " << l.markup);
      const double side = l.anchor.x() - ball_x;
      REQUIRE(std::abs(side) > 1);  // each arrow stands beside the ball, not through it
      CHECK(l.direction.x() * side > 0);
      ++labels;
    }
  }
  CHECK(labels > 50);
}

TEST_CASE("bouncing ball: what is drawn is the force list, and the v arrow is to scale and never passes the ground",
          "[scene][diagram][free-body]") {
  Run r = run_of("bouncing_ball");
  auto& d = diagram_as<BouncingBallDiagram>(r);
  double per_speed = 0;
  bool lifted = false;
  for (const auto& row : r.rows) {
    const Arrow v = d.velocity_arrow(row);
    CHECK(std::min(v.from.y(), v.to.y()) >= -1e-12);  // the ground is y = 0
    CHECK(v.from.x() == v.to.x());
    if (std::abs(row[2]) > 0.1) {
      if (per_speed == 0) per_speed = (v.to.y() - v.from.y()) / row[2];
      CHECK((v.to.y() - v.from.y()) / row[2] == Approx(per_speed).epsilon(1e-12));
    }
    // From the ball's centre level, unless that would take it into the ground.
    const double centre = d.ball_center(row).y(), reach = centre + (v.to.y() - v.from.y());
    if (reach >= 0) {
      CHECK(v.from.y() == Approx(centre).margin(1e-12));
    } else {
      CHECK(v.to.y() == Approx(0).margin(1e-12));
      lifted = true;
    }
  }
  CHECK(per_speed > 0);
  CHECK(lifted);  // the instants before an impact
  // The frame's labels are the forces' labels and v (none for v at rest).
  for (size_t i : {size_t(3), r.rows.size() - 1}) {
    std::vector<std::string> expected;
    for (const DrawnForce& f : d.forces(r.rows[i])) expected.push_back(f.label);
    if (!BouncingBallDiagram::at_rest(r.rows[i])) expected.push_back("<i>v</i>");
    CHECK(drawn_labels(d, r.world, r.rows[i]) == expected);
  }
  CHECK(drawn_labels(d, r.world, r.rows.back()) ==
        std::vector<std::string>{"<i>mg</i>", "<i>N</i> = <i>mg</i>"});
}

TEST_CASE("sliding box: kinetic friction mu N against v while sliding, static friction equal and opposite to the "
          "spring once stuck, N up from the floor in every phase",
          "[scene][diagram][free-body]") {
  const double mu = 0.15;
  Run r = run_of("sliding_box", {{"mu", "0.15"}});
  auto& d = diagram_as<SlidingBoxDiagram>(r);
  const Sticking stuck = sticking(mu);
  REQUIRE(stuck.t < r.rows.back()[0]);
  const double m = d.friction_magnification();
  int sliding = 0, resting = 0;
  for (const auto& row : r.rows) {
    const auto forces = d.forces(row);
    auto find = [&](ForceKind k) {
      const auto it = std::find_if(forces.begin(), forces.end(), [k](const DrawnForce& f) { return f.kind == k; });
      REQUIRE(it != forces.end());
      return *it;
    };
    const DrawnForce spring = find(ForceKind::spring), friction = find(ForceKind::friction);
    const Arrow w = find(ForceKind::weight).arrow, n = find(ForceKind::normal).arrow;
    // N up from the floor (y = 0) and mg down, equal and opposite.
    CHECK(n.from.y() == 0);
    CHECK(n.to.y() > 0);
    CHECK(n.to.y() - n.from.y() == Approx(w.from.y() - w.to.y()).epsilon(1e-12));
    const double per = (spring.arrow.to.x() - spring.arrow.from.x()) / -row[1];  // s(u) = u
    const double f = (friction.arrow.to.x() - friction.arrow.from.x()) / (m * per);
    if (row[0] == 0) {
      // Released from rest at u = 1 > mu: friction at its limit against the motion to come.
      CHECK(d.phase(row) == SlidingBoxDiagram::Phase::turning);
      CHECK(f == Approx(mu).epsilon(1e-9));
    } else if (row[0] < stuck.t - 1e-9) {
      ++sliding;
      REQUIRE(row[2] != 0);
      CHECK(f == Approx(row[2] > 0 ? -mu : mu).epsilon(1e-9));  // mu N against v
      CHECK(friction.label.find("kinetic") != std::string::npos);
      CHECK(d.phase(row) == SlidingBoxDiagram::Phase::sliding);
    } else if (row[0] > stuck.t + 1e-9) {
      ++resting;
      CHECK(row[1] == Approx(stuck.u).margin(1e-9));
      CHECK(f == Approx(row[1]).epsilon(1e-9));  // the spring pulls -u, friction holds with +u
      CHECK(std::abs(f) <= mu);
      CHECK(friction.label.find("static") != std::string::npos);
    }
  }
  CHECK(sliding > 50);
  CHECK(resting > 5);
  // The moment it sticks: at rest at the turning point, static friction takes the spring's force.
  const std::vector<double> sticks = {stuck.t, stuck.u, 0};
  CHECK(d.phase(sticks) == SlidingBoxDiagram::Phase::stuck);
  // A turning point the spring can leave: |s(u)| > mu N, friction at its limit against the coming motion.
  const std::vector<double> turning = {M_PI, -(1 - 2 * mu), 0};
  CHECK(d.phase(turning) == SlidingBoxDiagram::Phase::turning);
  for (const DrawnForce& f : d.forces(turning))
    if (f.kind == ForceKind::friction) {
      CHECK(f.arrow.to.x() < f.arrow.from.x());  // the spring pushes it right: friction points left
      CHECK(f.label.find("μ<i>N</i> at the turn") != std::string::npos);
    }
  // The frame shows exactly these forces' labels (and u's dimension).
  for (const auto& row : {r.rows[4], r.rows.back()}) {
    std::vector<std::string> expected = {"<i>u</i>"};
    for (const DrawnForce& f : d.forces(row)) expected.push_back(f.label);
    CHECK(drawn_labels(d, r.world, row) == expected);
  }
  CHECK(key_names(d) == std::vector<std::string>{"−s(u) spring", "f friction", "mg, N weight, floor"});
}

TEST_CASE("the spring's force is named compressed when u < 0 and it pushes, stretched when it pulls",
          "[scene][diagram][free-body]") {
  Run r = run_of("spring");
  auto& d = diagram_as<OscillatorDiagram>(r);
  int compressed = 0, stretched = 0;
  for (size_t i = 1; i < r.rows.size(); i += 7) {
    const auto& row = r.rows[i];
    const Arrow a = d.force_arrows(row).front();
    const std::string label = drawn_labels(d, r.world, row).at(1);  // after u's dimension
    if (row[1] < 0) {
      ++compressed;
      CHECK(a.to.x() > a.from.x());  // pushes the body away from the wall
      CHECK(label == "−<i>ku</i>, compressed");
    } else if (row[1] > 0) {
      ++stretched;
      CHECK(a.to.x() < a.from.x());  // pulls it toward the wall
      CHECK(label == "−<i>ku</i>, stretched");
    }
  }
  CHECK(compressed > 5);
  CHECK(stretched > 5);
}

TEST_CASE("keys list exactly the forces a run has: no friction without mu, no damper without b",
          "[scene][diagram][free-body]") {
  const Run frictionless = run_of("sliding_box", {{"mu", "0"}});
  for (const auto& row : frictionless.rows) {
    const auto drawn = kinds(diagram_as<SlidingBoxDiagram>(frictionless).forces(row));
    CHECK(std::count(drawn.begin(), drawn.end(), ForceKind::friction) == 0);
  }
  CHECK(key_names(*frictionless.diagram) == std::vector<std::string>{"−s(u) spring", "mg, N weight, floor"});
  CHECK(frictionless.diagram->force_key()->note == "<i>mg</i>, <i>N</i> not to scale");  // no "f drawn ×5"

  const Run undamped = run_of("bumpy_road", {{"b", "0"}});
  for (const auto& row : undamped.rows) CHECK(diagram_as<BumpyRoadDiagram>(undamped).forces(row).size() == 1);
  CHECK(key_names(*undamped.diagram) == std::vector<std::string>{"−ku spring beyond its static load"});
  const Run damped = run_of("bumpy_road");
  for (const auto& row : damped.rows)
    CHECK(kinds(diagram_as<BumpyRoadDiagram>(damped).forces(row)) == std::vector{ForceKind::spring, ForceKind::damper});
  CHECK(key_names(*damped.diagram).size() == 2);

  CHECK(key_names(*run_of("spring").diagram) == std::vector<std::string>{"−ku spring"});
  CHECK(key_names(*run_of("spring_dashpot", {{"b", "0"}}).diagram) ==
        std::vector<std::string>{"−ku spring", "F(t) driving force"});
  CHECK(key_names(*run_of("spring_dashpot").diagram) ==
        std::vector<std::string>{"−ku spring", "−bu′ damping", "F(t) driving force"});
}

TEST_CASE("a comparison's key is its first run's forces: the ghosts draw no arrows",
          "[scene][diagram][free-body][comparison]") {
  // mu = 0 first, mu = 0.2 as the ghost: no friction is drawn, so none is named.
  for (const auto& [first, ghost, has_friction] : {std::tuple{"0", "0.2", false}, std::tuple{"0.2", "0", true}}) {
    Run a = run_of("sliding_box", {{"mu", first}}), b = run_of("sliding_box", {{"mu", ghost}});
    REQUIRE(a.rows.size() == b.rows.size());
    std::vector<ComparisonDiagram::Member> members;
    const SceneConfig config = load_scene("sliding_box");
    auto member = [&](const char* mu) {
      SceneConfig c = config;
      apply_setting(c, {"mu", mu, "test"});
      const Parameters p = model_parameters_of(c);
      return diagram_for(c).make({c, p, find_model(c.model).build(p)->info()});
    };
    members.push_back({member(first), MemberColumns{1, 3}, {"a", render::palette::blue}});
    members.push_back({member(ghost), MemberColumns{3, 3}, {"b", render::palette::green}});
    ComparisonDiagram comparison(std::move(members), false, "exact");
    WorldBox world;
    world.setEmpty();
    std::vector<std::vector<double>> rows;
    for (size_t i = 0; i < a.rows.size(); ++i) {
      rows.push_back({a.rows[i][0], a.rows[i][1], a.rows[i][2], b.rows[i][1], b.rows[i][2]});
      comparison.record(rows.back(), world);
    }
    comparison.finish_recording(world);
    INFO("first mu = " << first);
    const auto names = key_names(comparison);
    CHECK(std::count(names.begin(), names.end(), "f friction") == (has_friction ? 1 : 0));
    // Every label drawn in a frame is the first run's: a friction label only when it has friction.
    size_t frictions = 0;
    for (size_t i = 5; i < rows.size(); i += 40)
      for (const std::string& l : drawn_labels(comparison, world, rows[i])) frictions += l.rfind("<i>f</i>", 0) == 0;
    CHECK((frictions > 0) == has_friction);
  }
}

TEST_CASE("no force arrow passes through the ground or a wall, in any state", "[scene][diagram][free-body]") {
  // The floor is y = 0 and the wall x = 0 in the horizontal systems and the ball's scene.
  auto inside = [](const Arrow& a) { return std::min(a.from.y(), a.to.y()) >= -1e-12 && std::min(a.from.x(), a.to.x()) >= 0; };
  for (const char* mu : {"0.02", "0.08", "0.3", "2"}) {
    const Run r = run_of("sliding_box", {{"mu", mu}});
    for (const auto& row : r.rows)
      for (const DrawnForce& f : diagram_as<SlidingBoxDiagram>(r).forces(row)) CHECK(inside(f.arrow));
  }
  for (const char* scene : {"spring", "spring_dashpot"}) {
    const Run r = run_of(scene);
    for (const auto& row : r.rows)
      for (const Arrow& a : diagram_as<OscillatorDiagram>(r).force_arrows(row)) CHECK(inside(a));
  }
  for (const Settings& s : {Settings{}, Settings{{"V", "3"}}, Settings{{"h0", "0.2"}, {"C_R", "0.95"}}}) {
    const Run r = run_of("bouncing_ball", s);
    auto& d = diagram_as<BouncingBallDiagram>(r);
    for (const auto& row : r.rows) {
      CHECK(std::min(d.velocity_arrow(row).from.y(), d.velocity_arrow(row).to.y()) >= -1e-12);
      for (const DrawnForce& f : d.forces(row)) CHECK(std::min(f.arrow.from.y(), f.arrow.to.y()) >= -1e-12);
    }
  }
  // The road's car: the arrows stay on the body, above its axle, never in the road.
  const Run road = run_of("bumpy_road");
  auto& car = diagram_as<BumpyRoadDiagram>(road);
  for (const auto& row : road.rows)
    for (const DrawnForce& f : car.forces(row)) CHECK(std::min(f.arrow.from.y(), f.arrow.to.y()) > car.axle(row).y());
}

TEST_CASE("the bumpy road's spring and damper arrows point against u and u' (-ku, -bu')", "[scene][diagram][free-body]") {
  const Run road = run_of("bumpy_road");
  int up = 0, down = 0;
  for (const auto& row : road.rows) {
    const auto forces = diagram_as<BumpyRoadDiagram>(road).forces(row);
    REQUIRE(forces.size() == 2);
    const double spring = forces[0].arrow.to.y() - forces[0].arrow.from.y();
    const double damper = forces[1].arrow.to.y() - forces[1].arrow.from.y();
    if (std::abs(row[1]) > 1e-9) CHECK(spring * row[1] < 0);  // y grows upwards in the world: u up, the spring pulls down
    if (std::abs(row[2]) > 1e-9) CHECK(damper * row[2] < 0);
    (spring > 0 ? up : down)++;
  }
  CHECK(up > 5);  // the run goes both ways
  CHECK(down > 5);
}
