// Labels are placed clear of everything the diagram draws, for every
// built-in scene, both diagram layouts, three frame sizes and 24 moments
// of each run: checked from the kit's recorded outlines, not from pixels.
#include <catch2/catch.hpp>
#include <cmath>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "render/draw/canvas.hpp"
#include "render/labels/drawing_record.hpp"
#include "render/labels/outline.hpp"
#include "scenes/config/scene_config.hpp"
#include "scene_run_support.hpp"
#include "scenes/scene_factory.hpp"
#include "scenes/system_scene.hpp"

using vibra::render::Canvas;
using vibra::render::DrawingRecord;
using vibra::render::OutlineKind;
using vibra::render::OutlineShape;
using vibra::render::PixelRect;
using vibra::render::PlacedLabel;

namespace {

struct Setup {
  std::string scene;
  std::vector<std::pair<std::string, std::string>> settings;
  int width, height;
};

std::string describe(const Setup& s) {
  std::ostringstream out;
  out << s.scene;
  for (const auto& [k, v] : s.settings) out << " --set " << k << "=" << v;
  out << " --size " << s.width << "x" << s.height;
  return out.str();
}

/// The box shrunk by half a pixel: boxes that only touch do not overlap.
PixelRect inset(const PixelRect& r) { return {r.x + 0.5, r.y + 0.5, r.w - 1, r.h - 1}; }

/// What a label's box overlaps in the frame's outline, if anything.
std::string overlap_of(const DrawingRecord& frame, size_t label) {
  const PlacedLabel& placed = frame.placed[label];
  for (const OutlineShape& shape : frame.outline.shapes()) {
    const bool itself = shape.kind == OutlineKind::label && shape.name == placed.request.markup &&
                        shape.bounds.x == placed.box.x && shape.bounds.y == placed.box.y;
    if (itself || !vibra::render::overlaps(inset(placed.box), shape)) continue;
    return std::string(vibra::render::outline_kind_name(shape.kind)) + (shape.name.empty() ? "" : " '" + shape.name + "'");
  }
  return {};
}

struct Verdict {
  int frames = 0, labels = 0;
};

/// Draws the run at 24 moments spread over it and checks every placed label
/// of every frame.
Verdict check_layout(const Setup& setup) {
  vibra::scenes::SceneConfig config = vibra::scenes::load_scene(setup.scene);
  for (const auto& [key, value] : setup.settings) vibra::scenes::apply_setting(config, {key, value, "test"});
  config.width = setup.width, config.height = setup.height;
  long long steps = 0;
  auto scene = vibra::test::scene_after_pre_pass(config, steps);

  std::vector<long long> moments;
  for (int k = 0; k < 24; ++k) moments.push_back(k * (steps - 1) / 23);
  Canvas canvas = Canvas::image(setup.width, setup.height);
  auto runs = vibra::scenes::build_scene_runs(config);
  std::vector<double> row(runs->width());
  Verdict verdict;
  long long step = 0;
  size_t next = 0;
  do {
    runs->row(row);
    scene->observe(row);
    if (next < moments.size() && step == moments[next]) {
      ++next;
      scene->draw(canvas, row);
      const DrawingRecord* frame = scene->last_layout();
      REQUIRE(frame);
      ++verdict.frames;
      for (size_t i = 0; i < frame->placed.size(); ++i) {
        const PlacedLabel& label = frame->placed[i];
        ++verdict.labels;
        INFO(describe(setup) << " at t = " << row[0] << ": label '" << label.request.markup << "'");
        CHECK(overlap_of(*frame, i) == "");
        CHECK(label.free);
      }
    }
    ++step;
  } while (runs->advance() && next < moments.size());
  return verdict;
}

const std::vector<std::string> kScenes = {"pendulum", "pendulum_book", "spring",        "spring_dashpot",
                                          "washing_machine", "sliding_box", "bumpy_road", "bouncing_ball",
                                          "rlc",             "elastic_pendulum", "orbit"};

void check_all_scenes(int width, int height) {
  for (const std::string& scene : kScenes)
    for (const char* layout : {"fbd", "fbd+plot"}) {
      const Verdict v = check_layout({scene, {{"layout", layout}}, width, height});
      INFO(scene << " " << layout << " at " << width << "x" << height);
      CHECK(v.frames == 24);
      CHECK(v.labels > 0);
    }
}

}  // namespace

TEST_CASE("labels overlap nothing the diagram draws, at 640x360", "[labels]") { check_all_scenes(640, 360); }
TEST_CASE("labels overlap nothing the diagram draws, at 1280x720", "[heavy][labels]") { check_all_scenes(1280, 720); }
TEST_CASE("labels overlap nothing the diagram draws, at 1920x1080", "[heavy][labels]") { check_all_scenes(1920, 1080); }

TEST_CASE("labels overlap nothing in comparisons, energy bars and large swings", "[labels]") {
  const std::vector<Setup> setups = {
      {"spring", {{"compare", "scheme=forward-euler,crank-nicolson,rk4"}}, 1280, 720},
      {"pendulum", {{"compare", "Theta=20,60,120"}}, 1280, 720},
      {"pendulum", {{"Theta", "170"}, {"alpha", "0"}}, 1280, 720},
      {"spring_dashpot", {{"energy_bars", "true"}}, 1280, 720},
      {"sliding_box", {}, 640, 360},
  };
  for (const Setup& s : setups) {
    const Verdict v = check_layout(s);
    INFO(describe(s));
    CHECK(v.frames == 24);
    CHECK(v.labels > 0);
  }
}

TEST_CASE("labels keep 8 px (at 720p) clear of the energy bars: their area ends there, and no label crosses it",
          "[labels]") {
  for (const auto& [width, height] : {std::pair{640, 360}, std::pair{1280, 720}}) {
    vibra::scenes::SceneConfig config = vibra::scenes::load_scene("spring_dashpot");
    vibra::scenes::apply_setting(config, {"energy_bars", "true", "test"});
    config.width = width, config.height = height;
    long long steps = 0;
    auto scene = vibra::test::scene_after_pre_pass(config, steps);
    auto* system = dynamic_cast<vibra::scenes::SystemScene*>(scene.get());
    REQUIRE(system);
    Canvas canvas = Canvas::image(width, height);
    auto runs = vibra::scenes::build_scene_runs(config);
    std::vector<double> row(runs->width());
    long long step = 0;
    int frames = 0;
    do {
      runs->row(row);
      scene->observe(row);
      if (step % std::max(1LL, steps / 24) != 0) continue;
      scene->draw(canvas, row);
      ++frames;
      const auto bars = system->bars_area();
      REQUIRE(bars);
      const double limit = bars->x - 8 * canvas.scale();
      const PixelRect area = system->label_area(canvas.scale());
      INFO(width << "x" << height << " at t = " << row[0]);
      CHECK(area.x + area.w == Approx(limit));
      for (const PlacedLabel& label : scene->last_layout()->placed) {
        INFO("label '" << label.request.markup << "'");
        CHECK(label.box.x + label.box.w <= limit + 1e-9);
      }
    } while (++step, runs->advance());
    CHECK(frames >= 24);
  }
}

TEST_CASE("an outline knows what a box overlaps: strokes by their width, fills by their inside", "[labels]") {
  Canvas canvas = Canvas::image(200, 100);
  DrawingRecord record;
  canvas.record_into(&record);
  cairo_t* cr = canvas.cr();
  cairo_set_line_width(cr, 10);
  cairo_move_to(cr, 10, 50);
  cairo_line_to(cr, 190, 50);
  canvas.stroke();
  cairo_rectangle(cr, 20, 70, 40, 20);
  canvas.fill();
  canvas.record_into(nullptr);
  REQUIRE(record.outline.shapes().size() == 2);
  const OutlineShape& line = record.outline.shapes()[0];
  const OutlineShape& box = record.outline.shapes()[1];
  CHECK(vibra::render::overlaps({90, 52, 10, 10}, line));   // within the stroke's half width of 5
  CHECK(!vibra::render::overlaps({90, 56, 10, 10}, line));  // 6 below the centre line: clear
  CHECK(vibra::render::overlaps({30, 75, 5, 5}, box));      // wholly inside the fill
  CHECK(!vibra::render::overlaps({70, 75, 5, 5}, box));
  CHECK(vibra::render::overlaps({55, 60, 10, 12}, box));    // across its corner
}
