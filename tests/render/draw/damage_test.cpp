// Damage tracking: a frame redrawn only where something changed must be the
// very frame a full redraw gives, for every scene and layout, and nothing may
// change outside what the canvas reports.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "core/models/model.hpp"
#include "render/draw/canvas.hpp"
#include "render/draw/damage.hpp"
#include "scenes/config/scene_config.hpp"
#include "scenes/scene_factory.hpp"

using vibra::render::Canvas;
using vibra::render::Damage;

namespace {

std::vector<std::uint8_t> pixels(const Canvas& canvas) {
  const std::size_t row = std::size_t(canvas.width()) * 4;
  std::vector<std::uint8_t> out(row * canvas.height());
  for (int y = 0; y < canvas.height(); ++y)
    std::memcpy(out.data() + row * y, canvas.data() + std::size_t(y) * canvas.stride(), row);
  return out;
}

/// Pixels that differ between two frames but lie outside `changed`.
long long unreported_changes(const std::vector<std::uint8_t>& before, const std::vector<std::uint8_t>& after,
                             const Damage& changed, int width, int height) {
  long long count = 0;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const std::size_t i = (std::size_t(y) * width + x) * 4;
      if (std::memcmp(&before[i], &after[i], 4) != 0 && !changed.intersects(x, y, x + 1, y + 1)) ++count;
    }
  return count;
}

/// The area `changed` covers, as a fraction of the picture (rectangles may overlap: an upper bound).
double covered_fraction(const Damage& changed, int width, int height) {
  if (changed.all()) return 1;
  double area = 0;
  for (const auto& r : changed.rects()) area += double(r.x1 - r.x0) * (r.y1 - r.y0);
  return area / (double(width) * height);
}

struct Run {
  double largest_covered = 0, mean_covered = 0;
  double last_covered = 0;  ///< the last frame's
};

vibra::scenes::SceneConfig small_scene(const std::vector<std::pair<std::string, std::string>>& settings,
                                       const std::string& scene = "pendulum") {
  vibra::scenes::SceneConfig config = vibra::scenes::load_scene(scene);
  for (const auto& [key, value] : settings) vibra::scenes::apply_setting(config, {key, value, "test"});
  config.width = 480, config.height = 270;
  return config;
}

/// Scenes of `config` that have seen the whole run (the render's pre-pass).
std::vector<std::unique_ptr<vibra::scenes::Scene>> recorded_scenes(const vibra::scenes::SceneConfig& config,
                                                                   int count) {
  auto pre_pass = vibra::scenes::build_scene_runs(config);
  std::vector<std::unique_ptr<vibra::scenes::Scene>> scenes;
  for (int i = 0; i < count; ++i) scenes.push_back(vibra::scenes::make_scene_for(config, *pre_pass, "test"));
  std::vector<double> row(pre_pass->width());
  do {
    pre_pass->row(row);
    for (auto& scene : scenes) scene->record(row);
  } while (pre_pass->advance());
  return scenes;
}

/// Draws `frames` solver steps of a scene twice, by two scenes of the same
/// config: on a canvas that tracks damage and on one that redraws in full.
Run compare_redraws(const std::vector<std::pair<std::string, std::string>>& settings, int frames,
                    const std::string& scene = "pendulum") {
  const vibra::scenes::SceneConfig config = small_scene(settings, scene);
  auto scenes = recorded_scenes(config, 2);
  auto& tracked_scene = scenes[0];
  auto& full_scene = scenes[1];

  Canvas tracked = Canvas::image(config.width, config.height), full = Canvas::image(config.width, config.height);
  tracked.track_damage();
  auto trajectory = vibra::scenes::build_scene_runs(config);
  std::vector<double> row(trajectory->width());
  std::vector<std::uint8_t> previous;
  Run run;
  for (int k = 0; k < frames; ++k) {
    trajectory->row(row);
    tracked_scene->observe(row);
    full_scene->observe(row);
    tracked.begin_frame();
    tracked_scene->draw(tracked, row);
    tracked.flush();
    full_scene->draw(full, row);
    full.flush();

    INFO("frame " << k);
    const std::vector<std::uint8_t> now = pixels(tracked);
    REQUIRE(now == pixels(full));
    if (k > 0) {
      CHECK(unreported_changes(previous, now, tracked.changed(), config.width, config.height) == 0);
      const double covered = covered_fraction(tracked.changed(), config.width, config.height);
      run.largest_covered = std::max(run.largest_covered, covered);
      run.mean_covered += covered / (frames - 1);
      run.last_covered = covered;
    }
    previous = now;
    if (!trajectory->advance()) break;
  }
  return run;
}

}  // namespace

TEST_CASE("damage: boxes widen to whole pixels, clip to the picture, and anything odd means all", "[damage]") {
  Damage d(100, 50);
  CHECK(d.empty());
  d.add(10.2, 20.7, 30.1, 25.0, 2);
  REQUIRE(d.rects().size() == 1);
  CHECK(d.rects()[0].x0 == 8);
  CHECK(d.rects()[0].y0 == 18);
  CHECK(d.rects()[0].x1 == 33);
  CHECK(d.rects()[0].y1 == 27);
  CHECK(d.intersects(32, 26, 40, 40));
  CHECK_FALSE(d.intersects(33, 0, 40, 50));
  d.add(-50, -50, -10, -10);  // off the picture: nothing
  d.add(90, 40, 500, 500, 0);
  REQUIRE(d.rects().size() == 2);
  CHECK(d.rects()[1].x1 == 100);
  CHECK(d.rects()[1].y1 == 50);
  d.add(0, 0, std::numeric_limits<double>::quiet_NaN(), 1);
  CHECK(d.all());
  CHECK(d.intersects(99, 49, 100, 50));
  d.clear();
  CHECK(d.empty());
  d.add(-1e300, -1e300, 1e300, 1e300);  // huge: clipped, no overflow
  REQUIRE(d.rects().size() == 1);
  CHECK(d.rects()[0].x0 == 0);
  CHECK(d.rects()[0].x1 == 100);
}

TEST_CASE("damage: the changed columns of a band of rows are sorted, merged spans", "[damage]") {
  Damage d(100, 50);
  std::vector<std::pair<int, int>> spans;
  d.add(50, 0, 60, 10, 0);
  d.add(10, 5, 20, 15, 0);
  d.add(15, 0, 30, 3, 0);   // overlaps the second: merged
  d.add(70, 20, 80, 30, 0);  // other rows
  d.spans(0, 10, spans);
  CHECK(spans == std::vector<std::pair<int, int>>{{10, 30}, {50, 60}});
  d.spans(12, 14, spans);
  CHECK(spans == std::vector<std::pair<int, int>>{{10, 20}});
  d.spans(40, 50, spans);
  CHECK(spans.empty());
  d.add_all();
  d.spans(40, 50, spans);
  CHECK(spans == std::vector<std::pair<int, int>>{{0, 100}});
}

TEST_CASE("damage: redrawing only what changed gives the full redraw, pixel for pixel, in every layout",
          "[heavy][damage]") {
  SECTION("the diagram alone: little of the picture changes") {
    const Run run = compare_redraws({{"layout", "fbd"}}, 80);
    CHECK(run.mean_covered < 0.4);  // the bob (L/12) and the forces' casings move with it
  }
  SECTION("the diagram beside its growing plots") {
    const Run run = compare_redraws({{"layout", "fbd+plot"}}, 80);
    CHECK(run.mean_covered < 0.6);
  }
  SECTION("moving windows in each mode") {
    for (const char* mode : {"movement", "drawing", "jumps"}) {
      INFO(mode);
      compare_redraws({{"layout", "plot"}, {"window", "1periods"}, {"window_mode", mode}}, 120);
    }
  }
  SECTION("other models' plots, with the exact solution") {
    compare_redraws({{"model", "undamped"}, {"layout", "plot"}}, 60);
    compare_redraws({{"model", "elastic-pendulum"}, {"layout", "plot"}}, 60);
  }
  SECTION("every built-in scene's diagram, alone and beside its panels") {
    for (const std::string& scene : vibra::scenes::builtin_scene_names()) {
      for (const char* layout : {"fbd", "fbd+plot"}) {
        INFO(scene << ", layout " << layout);
        compare_redraws({{"layout", layout}}, 40, scene);
      }
    }
  }
}

TEST_CASE("damage: a comparison's ghosts, legend and blow-up notes redraw exactly too", "[damage][comparison]") {
  for (const char* layout : {"fbd", "fbd+plot", "plot", "grid"}) {
    INFO("layout " << layout);
    // Forward Euler blows up inside the frames drawn: its note appears.
    compare_redraws({{"layout", layout}, {"compare", "scheme=forward-euler,crank-nicolson,rk4"}, {"dt", "0.5"}}, 40,
                    "spring");
  }
  compare_redraws({{"compare", "Theta=10,60,120"}}, 40, "pendulum");
  compare_redraws({{"compare", "scheme=euler-cromer,pefrl"}, {"layout", "fbd"}}, 40, "orbit");
}

TEST_CASE("damage: after a run leaves the view, frames redraw only what moves, not a strip from where it left",
          "[damage][comparison]") {
  // Forward Euler leaves the view after about two periods; by the end of the
  // sixth the growing curves' strip must be as narrow as with runs that all
  // go on, not reach back to where it left.
  const Run left = compare_redraws({{"layout", "plot"}, {"compare", "scheme=forward-euler,rk4"}, {"periods", "6"}}, 360,
                                   "spring");
  const Run stayed = compare_redraws({{"layout", "plot"}, {"compare", "scheme=crank-nicolson,rk4"}, {"periods", "6"}},
                                     360, "spring");
  INFO("part of the last frame redrawn: " << left.last_covered << " with a run that left, " << stayed.last_covered
                                          << " without");
  CHECK(left.last_covered < 1.5 * stayed.last_covered + 0.02);
}

TEST_CASE("damage: a scene moved to a new canvas paints its whole background there", "[damage]") {
  const vibra::scenes::SceneConfig config = small_scene({{"layout", "fbd"}});
  auto scenes = recorded_scenes(config, 2);
  auto trajectory = vibra::find_model(config.model).build(vibra::scenes::model_parameters_of(config));
  std::vector<double> row(trajectory->width());
  trajectory->row(row);
  for (int canvas_number = 0; canvas_number < 3; ++canvas_number) {
    // Each canvas dies before the next is made, which may get the same address.
    Canvas tracked = Canvas::image(config.width, config.height);
    tracked.track_damage();
    tracked.begin_frame();
    scenes[0]->draw(tracked, row);
    tracked.flush();
    Canvas full = Canvas::image(config.width, config.height);
    scenes[1]->draw(full, row);
    full.flush();
    INFO("canvas " << canvas_number);
    CHECK(pixels(tracked) == pixels(full));
  }
}
