// The view is set by the bodies: at the hard moments (a pendulum near the top
// or over it, a machine at resonance, huge forces) the system is drawn at least
// a third of its part's short side, and arrows too long for it are clipped with
// a break mark instead of shrinking the drawing (docs/drawing.md).
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>

#include "render/draw/canvas.hpp"
#include "render/labels/drawing_record.hpp"
#include "scene_run_support.hpp"
#include "scenes/diagrams/forces/force_scale.hpp"
#include "scenes/config/scene_config.hpp"
#include "scenes/scene_factory.hpp"
#include "scenes/system_scene.hpp"

using vibra::render::OutlineKind;
using vibra::render::PixelRect;

namespace {
struct HardMoment {
  std::string scene;
  std::vector<std::pair<std::string, std::string>> settings;
  double t;
  /// What the system's size is: a pendulum is its pivot and the bob's path
  /// over the run (the circle a swing over the top sweeps); a machine is
  /// itself on its floor, in the frame at t (its motion may be drawn smaller).
  bool swept;
};

/// What measures the system: a pendulum's bob and support (over the run);
/// the machine's box and drum (not its legs and floor, which its motion
/// stretches apart).
bool is_system(OutlineKind kind, bool swept) {
  return kind == OutlineKind::body || (swept && kind == OutlineKind::ground);
}

/// The larger side of what the system's bodies and support cover (see
/// HardMoment::swept; arrows, labels and text left out), and the short side
/// of the diagram's part of the frame, in pixels.
std::pair<double, double> system_and_part(const HardMoment& m, int width, int height) {
  vibra::scenes::SceneConfig config = vibra::scenes::load_scene(m.scene);
  for (const auto& [k, v] : m.settings) vibra::scenes::apply_setting(config, {k, v, "test"});
  config.width = width, config.height = height;
  long long steps = 0;
  auto scene = vibra::test::scene_after_pre_pass(config, steps);
  auto runs = vibra::scenes::build_scene_runs(config);
  std::vector<double> row(runs->width());
  double x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY;
  bool hard_moment_drawn = false;
  for (long long step = 0; step < steps; ++step) {
    runs->row(row);
    scene->observe(row);
    const bool hard = !hard_moment_drawn && row[0] >= m.t;
    if (hard || (m.swept && step % std::max(1LL, steps / 48) == 0)) {
      vibra::render::Canvas canvas = vibra::render::Canvas::image(width, height);
      scene->draw(canvas, row);
      REQUIRE(scene->last_layout());
      for (const auto& s : scene->last_layout()->outline.shapes())
        if (is_system(s.kind, m.swept)) {
          x0 = std::min(x0, s.bounds.x), y0 = std::min(y0, s.bounds.y);
          x1 = std::max(x1, s.bounds.x + s.bounds.w), y1 = std::max(y1, s.bounds.y + s.bounds.h);
        }
      hard_moment_drawn = hard_moment_drawn || hard;
    }
    if (!runs->advance()) break;
  }
  CHECK(hard_moment_drawn);
  const auto* system = dynamic_cast<const vibra::scenes::SystemScene*>(scene.get());
  REQUIRE(system);
  const PixelRect part = system->diagram_area();
  if (m.scene == "pendulum") {
    // The view is set by the bob's path, within the 2 x 2 square of a wire of
    // length 1, and the 0.5 L of room its arrows get: no arrow sets it.
    INFO("world box " << system->world_box().min().transpose() << " to " << system->world_box().max().transpose());
    CHECK(system->world_box().sizes().maxCoeff() <= 2 * (1 + 0.5) + 1e-9);
  }
  return {std::max(x1 - x0, y1 - y0), std::min(part.w, part.h)};
}
}  // namespace

TEST_CASE("the view is set by the bodies: every system at least a third of its part's short side at its hard moments",
          "[scene][diagram][extent]") {
  const std::vector<HardMoment> moments = {
      {"pendulum", {{"Theta", "170"}}, 1, true},                      // near the top, fast drag
      {"pendulum", {{"Theta", "10"}, {"Omega", "150"}}, 1, true},     // over the top
      {"pendulum", {{"Theta", "30"}, {"Omega", "3000"}}, 0.5, true},  // S = omega^2 in the thousands
      {"washing_machine", {{"gamma", "1"}}, 20, false},               // resonance
      {"washing_machine", {{"gamma", "1"}, {"beta", "0"}}, 100, false},  // undamped: u grows without bound
      {"elastic_pendulum", {{"beta", "0.8"}, {"Theta", "90"}, {"eps", "0.2"}}, 3, true},
      {"elastic_pendulum", {{"beta", "0.8"}, {"Theta", "170"}}, 3, true},                // over its pivot, turn after turn
      {"elastic_pendulum", {{"beta", "0.8"}, {"Theta", "30"}, {"eps", "3"}}, 1, true},  // stretched four times
  };
  for (const auto& m : moments)
    for (const auto& [w, h] : {std::pair{640, 360}, std::pair{1920, 1080}}) {
      INFO(m.scene << " " << (m.settings.empty() ? "" : m.settings.front().first + "=" + m.settings.front().second)
                   << " at t = " << m.t << ", " << w << "x" << h);
      const auto [system, part] = system_and_part(m, w, h);
      CHECK(system >= part / 3);
    }
}

TEST_CASE("a force scale draws the largest force its longest, the reference at least 0.4 of that, and clips the rest",
          "[scene][diagram][extent]") {
  vibra::scenes::ForceScale scale;
  scale.set_longest(2);
  scale.set_reference(1);
  for (double f : {0.5, -1.0, 2.0}) scale.see(f);
  // Largest 2 fits: 1 world unit per force, the reference 1 at 1 > 0.4 * 2.
  CHECK(scale.per_force() == Approx(1));
  CHECK_FALSE(scale.clips(scale.length(2)));
  // At resonance the spring force is 20 times the forcing: 20 at 2/20 per force
  // would draw the forcing 0.1 long, so the forcing gets 0.4 * 2 and 20 is clipped.
  scale.see(20);
  CHECK(scale.per_force() == Approx(0.4 * 2 / 1));
  CHECK(scale.length(1) == Approx(0.8));
  const vibra::scenes::Arrow spring{{1, 1}, {1, 1 + scale.length(20)}};
  CHECK(scale.clips((spring.to - spring.from).norm()));
  const vibra::scenes::Arrow drawn = scale.clipped(spring);
  CHECK((drawn.to - drawn.from).norm() == Approx(2));
  CHECK((drawn.to - drawn.from).normalized().isApprox((spring.to - spring.from).normalized()));
  CHECK(drawn.from == spring.from);
}
