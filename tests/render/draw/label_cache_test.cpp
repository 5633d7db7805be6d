// Labels kept as images (LabelCache): pasted, they give the pixels of setting
// them afresh, they mark where they land, and memory stays bounded.
#include <catch2/catch.hpp>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "render/draw/canvas.hpp"
#include "render/draw/label_cache.hpp"
#include "render/draw/text.hpp"

using namespace vibra::render;

namespace {
/// The largest difference of any channel of any pixel between two canvases.
int largest_difference(const Canvas& a, const Canvas& b) {
  a.flush(), b.flush();
  int largest = 0;
  for (int y = 0; y < a.height(); ++y)
    for (int x = 0; x < 4 * a.width(); ++x)
      largest = std::max(largest, std::abs(int(a.data()[y * a.stride() + x]) - int(b.data()[y * b.stride() + x])));
  return largest;
}

/// Labels of every kind the scenes draw: italics, Greek, subscripts, a halo
/// over a line, anchors, an ellipsis.
void draw_labels(Canvas& canvas) {
  canvas.clear(palette::paper);
  cairo_set_source_rgb(canvas.cr(), 0.8, 0.2, 0.1);
  cairo_set_line_width(canvas.cr(), 6);
  cairo_move_to(canvas.cr(), 0, 60), cairo_line_to(canvas.cr(), 640, 60);
  canvas.stroke();
  TextStyle plain;
  TextStyle halo;
  halo.halo = true, halo.size = 30, halo.color = palette::blue;
  TextStyle narrow;
  narrow.max_width = 90;
  for (int repeat = 0; repeat < 2; ++repeat) {  // the second time from the kept images
    draw_text(canvas, {100, 60}, "−<i>ku</i>", halo, Anchor::left);
    draw_text(canvas, {320, 60}, "θ<sub>0</sub> = 40°", halo);
    draw_text(canvas, {600, 120}, "<i>F</i>(<i>t</i>)", plain, Anchor::bottom_right);
    draw_text(canvas, {20, 200}, "a caption far too long for its ninety pixels", narrow, Anchor::top_left);
  }
}
}  // namespace

TEST_CASE("labels: pasted from kept images, the pixels of setting them afresh", "[render][text]") {
  Canvas kept = Canvas::image(640, 360), afresh = Canvas::image(640, 360);
  afresh.keep_labels(false);
  REQUIRE(kept.labels() != nullptr);
  REQUIRE(afresh.labels() == nullptr);
  draw_labels(kept);
  draw_labels(afresh);
  CHECK(kept.labels()->size() == 4);
  // The two-step composite rounds differently by at most a level or two at
  // antialiased edges; a misplaced glyph would differ by a hundred.
  CHECK(largest_difference(kept, afresh) <= 2);
  CHECK(text_size(kept, "θ<sub>0</sub> = 40°", {}) == text_size(afresh, "θ<sub>0</sub> = 40°", {}));
}

TEST_CASE("labels: a pasted label marks its box, halo included", "[render][text][damage]") {
  Canvas canvas = Canvas::image(400, 200);
  canvas.track_damage();
  TextStyle halo;
  halo.halo = true;
  for (int frame = 0; frame < 2; ++frame) {
    canvas.begin_frame();
    canvas.clear(palette::paper);
    canvas.begin_frame();
    draw_text(canvas, {200, 100}, "−<i>bu</i>′", halo);
    canvas.flush();
    // Every pixel that is not paper lies inside what was marked.
    const auto& rects = canvas.drawn().rects();
    REQUIRE(!rects.empty());
    for (int y = 0; y < canvas.height(); ++y)
      for (int x = 0; x < canvas.width(); ++x) {
        const auto pixel = reinterpret_cast<const std::uint32_t*>(canvas.data() + y * canvas.stride())[x];
        if (pixel == 0xffffffffu) continue;
        bool inside = false;
        for (const DamageRect& r : rects) inside |= x >= r.x0 && x < r.x1 && y >= r.y0 && y < r.y1;
        INFO("frame " << frame << " pixel " << x << "," << y);
        REQUIRE(inside);
      }
  }
}

TEST_CASE("labels: a label for every frame keeps memory bounded", "[render][text]") {
  Canvas canvas = Canvas::image(320, 180);
  TextStyle style;
  style.halo = true;
  std::size_t most = 0;
  for (int frame = 0; frame < 5000; ++frame) {
    draw_text(canvas, {160, 90}, "<i>t</i> = " + std::to_string(frame), style);
    most = std::max(most, canvas.labels()->size());
  }
  CHECK(most <= 2048);
  CHECK(canvas.labels()->size() < 5000);
}

TEST_CASE("labels: a canvas drawn at a fraction of a pixel sets them afresh", "[render][text]") {
  Canvas shifted = Canvas::image(320, 180), reference = Canvas::image(320, 180);
  reference.keep_labels(false);
  for (Canvas* c : {&shifted, &reference}) {
    c->clear(palette::paper);
    cairo_translate(c->cr(), 0.5, 0.25);  // kept images sit on whole pixels: not usable here
    draw_text(*c, {100, 90}, "<i>mg</i>", {});
  }
  CHECK(shifted.labels()->size() == 0);
  CHECK(largest_difference(shifted, reference) == 0);
}
