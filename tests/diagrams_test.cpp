// Every system's diagram: the arrows drawn are the model's forces at that
// instant (one scale per diagram), and nothing is clipped over the run at
// small and large frame sizes.
#include <catch2/catch.hpp>
#include <cmath>

#include "core/models/model.hpp"
#include "core/models/sliding_box_law.hpp"
#include "core/models/vibration_law.hpp"
#include "core/road_profile.hpp"
#include "render/canvas.hpp"
#include "scenes/bumpy_road_diagram.hpp"
#include "scenes/diagram_registry.hpp"
#include "scenes/oscillator_diagram.hpp"
#include "scenes/scene_factory.hpp"
#include "scenes/sliding_box_diagram.hpp"
#include "scenes/washing_machine_diagram.hpp"
#include "test_support.hpp"

using namespace vibra;
using namespace vibra::scenes;

namespace {
struct Recorded {
  SceneConfig config;
  std::unique_ptr<Diagram> diagram;
  std::vector<std::vector<double>> rows;
};

Recorded record(const std::string& scene, const std::vector<std::pair<std::string, std::string>>& settings = {}) {
  Recorded r{load_scene(scene), nullptr, {}};
  for (const auto& [k, v] : settings) apply_setting(r.config, {k, v, "test"});
  const Parameters p = model_parameters_of(r.config);
  auto run = find_model(r.config.model).build(p);
  r.diagram = diagram_for(r.config).make({r.config, p, run->info()});
  r.rows = vibra::test::rows(*run);
  WorldBox world;
  world.setEmpty();
  for (const auto& row : r.rows) r.diagram->record(row, world);
  r.diagram->finish_recording(world);
  return r;
}

template <class T>
T& as(const Recorded& r) {
  auto* d = dynamic_cast<T*>(r.diagram.get());
  REQUIRE(d != nullptr);
  return *d;
}
}  // namespace

TEST_CASE("spring-dashpot diagram: arrows are -s(u), -f(u') and F(t) to one scale, from the body's centre line",
          "[scene][diagram]") {
  const Recorded r = record("spring_dashpot");
  auto& d = as<OscillatorDiagram>(r);
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

TEST_CASE("spring diagram without damping or forcing draws the spring force alone", "[scene][diagram]") {
  const Recorded r = record("spring");
  auto& d = as<OscillatorDiagram>(r);
  for (const auto& row : r.rows) CHECK(d.force_arrows(row).size() == 1);
}

TEST_CASE("sliding box diagram: the friction arrow is kinetic while sliding, static at rest", "[scene][diagram]") {
  const Recorded r = record("sliding_box", {{"mu", "0.2"}});
  auto& d = as<SlidingBoxDiagram>(r);
  SlidingBoxLaw law;
  law.mu = 0.2;
  bool saw_rest = false;
  for (const auto& row : r.rows) {
    const auto arrows = d.force_arrows(row);
    const double per = (arrows[0].to.x() - arrows[0].from.x()) / -law.spring(row[1]);
    const double friction = (arrows[1].to.x() - arrows[1].from.x());
    const double m = d.friction_magnification();
    if (row[2] != 0) CHECK(friction == Approx(-0.2 * (row[2] > 0 ? 1 : -1) * per * m).epsilon(1e-9));
    if (row[2] == 0 && row[0] > 1) {
      saw_rest = true;
      // Static friction balances the spring: the two arrows are opposite, equal but for the magnification.
      CHECK(friction == Approx(-m * (arrows[0].to.x() - arrows[0].from.x())).margin(1e-12));
    }
  }
  CHECK(saw_rest);
  CHECK(d.friction_magnification() == 2);  // mu = 0.2 against a largest spring force 1: x2 makes it 40%
}

TEST_CASE("washing machine diagram: the drum's mass at the forcing's phase, arrows -u, -beta u', sin(gamma t)",
          "[scene][diagram]") {
  const Recorded r = record("washing_machine");
  auto& d = as<WashingMachineDiagram>(r);
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

TEST_CASE("bumpy road diagram: the wheel on the road, the body at L + u over the axle, arrows -k u and -b u'",
          "[scene][diagram]") {
  const Recorded r = record("bumpy_road");
  auto& d = as<BumpyRoadDiagram>(r);
  const Parameters p = model_parameters_of(r.config);
  const double R = p.number("R"), L = p.number("L"), k = p.number("k"), b = p.number("b");
  for (size_t i = 0; i < r.rows.size(); i += 5) {
    const auto& row = r.rows[i];
    CHECK(d.axle(row).y() == Approx(row[4] + R));
    CHECK(d.body_bottom(row) == Approx(row[4] + R + L + row[1]));
    const auto arrows = d.force_arrows(row);
    const double spring = arrows[0].to.y() - arrows[0].from.y(), damper = arrows[1].to.y() - arrows[1].from.y();
    if (std::abs(row[1]) > 1e-3 && std::abs(row[2]) > 1e-2) CHECK(damper / spring == Approx((b * row[2]) / (k * row[1])).epsilon(1e-9));
    // The view follows the vehicle.
    const auto view = d.view_at(row);
    REQUIRE(view);
    CHECK(view->center().x() == Approx(row[3]));
  }
}

TEST_CASE("nothing is clipped: over the run no drawing touches the frame's edge, small or large", "[scene][diagram]") {
  for (const std::string& name : builtin_scene_names()) {
    for (auto [w, h] : {std::pair{640, 360}, std::pair{1920, 1080}}) {
      SceneConfig config = load_scene(name);
      config.width = w, config.height = h, config.layout = Layout::fbd;
      const Parameters p = model_parameters_of(config);
      auto run = find_model(config.model).build(p);
      auto scene = make_scene(config, run->info(), "caption");
      auto rows = vibra::test::rows(*run);
      for (const auto& row : rows) scene->record(row);
      render::Canvas canvas = render::Canvas::image(w, h);
      canvas.track_damage();
      const size_t every = std::max<size_t>(1, rows.size() / 60);
      // A view that follows the body runs its ground off the frame on purpose.
      const bool follows = diagram_for(config).make({config, p, run->info()})->view_at(rows[0]).has_value();
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
