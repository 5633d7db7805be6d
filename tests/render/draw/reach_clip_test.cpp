// Paths that reach far beyond the picture: Cairo's 24.8 fixed point wraps
// coordinates beyond about 8 million pixels, so the kit clips every path to
// a box of a million pixels first, keeping each segment's direction.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <limits>

#include "render/draw/canvas.hpp"
#include "render/draw/elements/machine_elements.hpp"
#include "render/draw/reach_clip.hpp"
#include "render/draw/elements/shapes.hpp"

using vibra::render::Canvas;
using vibra::render::Point;

namespace {
/// The green channel of pixel (x, y): 0 where ink is, about 245 on paper.
int green(const Canvas& canvas, int x, int y) {
  return int((reinterpret_cast<const std::uint32_t*>(canvas.data() + y * canvas.stride())[x] >> 8) & 255);
}

Canvas paper() {
  Canvas canvas = Canvas::image(400, 200);
  canvas.clear(vibra::render::palette::paper);
  return canvas;
}

/// How many segments and moves the current path holds.
int path_points(cairo_t* cr) {
  cairo_path_t* path = cairo_copy_path(cr);
  int count = 0;
  for (int i = 0; i < path->num_data; i += path->data[i].header.length) ++count;
  cairo_path_destroy(path);
  return count;
}
}  // namespace

TEST_CASE("a line to a point far beyond any picture is drawn along its true direction", "[render][reach]") {
  for (const double far : {1e7, 1e12, 1e200}) {
    INFO("the far end at " << far << " pixels");
    Canvas canvas = paper();
    // Nearly level: one pixel of rise in every 1e10 across.
    vibra::render::draw_pixel_line(canvas, Point(20, 60.5), Point(far, 60.5 + far * 1e-10), {vibra::render::palette::ink, 1});
    // Down and right at 45 degrees.
    vibra::render::draw_pixel_line(canvas, Point(20.5, 100.5), Point(far, far + 80), {vibra::render::palette::ink, 1});
    canvas.flush();
    for (int x = 40; x < 400; x += 40) CHECK(green(canvas, x, 60) < 100);  // the level line, all the way
    CHECK(green(canvas, 100, 180) < 100);  // the slanted one, on its diagonal
    CHECK(green(canvas, 150, 100) > 200);  // and nothing where a wrapped path would cross
    CHECK(green(canvas, 300, 20) > 200);
  }
}

TEST_CASE("a polygon reaching far beyond is filled up to the picture's edge", "[render][reach]") {
  Canvas canvas = paper();
  cairo_t* cr = canvas.cr();
  const Point box[] = {{50, 50}, {1e200, 50}, {1e200, 150}, {50, 150}};
  vibra::render::add_polygon(cr, box);
  cairo_set_source_rgb(cr, 0, 0, 0);
  canvas.fill();
  canvas.flush();
  CHECK(green(canvas, 60, 100) == 0);
  CHECK(green(canvas, 399, 100) == 0);
  CHECK(green(canvas, 40, 100) > 200);
  CHECK(green(canvas, 200, 160) > 200);
}

TEST_CASE("a circle far away adds nothing, a huge one near the picture its visible arc", "[render][reach]") {
  Canvas canvas = paper();
  cairo_t* cr = canvas.cr();
  cairo_new_path(cr);
  vibra::render::add_arc(cr, Point(1e200, 100), 5, 0, 2 * M_PI);
  vibra::render::add_arc(cr, Point(-3e6, 100), 1e6, 0, 2 * M_PI);
  vibra::render::add_arc(cr, Point(std::numeric_limits<double>::quiet_NaN(), 100), 5, 0, 2 * M_PI);
  CHECK(path_points(cr) == 0);
  // A circle of radius 1e7 whose top passes through (200, 100).
  vibra::render::add_arc(cr, Point(200, 100 + 1e7), 1e7, 0, 2 * M_PI);
  cairo_set_source_rgb(cr, 0, 0, 0);
  cairo_set_line_width(cr, 2);
  canvas.stroke();
  canvas.flush();
  CHECK(green(canvas, 200, 100) < 100);
  CHECK(green(canvas, 100, 100) < 100);  // a million pixels of radius: flat across the picture
  CHECK(green(canvas, 200, 150) > 200);
}

TEST_CASE("paths within reach are the plain calls, and points that are not numbers are left out", "[render][reach]") {
  Canvas canvas = paper();
  cairo_t* cr = canvas.cr();
  const Point near[] = {{10, 10}, {100, 20}, {200, 150}};
  cairo_new_path(cr);
  vibra::render::add_polyline(cr, near);
  CHECK(path_points(cr) == 3);  // a move and two lines
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const Point broken[] = {{10, 10}, {nan, 20}, {200, 150}, {300, 150}};
  cairo_new_path(cr);
  vibra::render::add_polyline(cr, broken);
  CHECK(path_points(cr) == 2);  // only the last segment: a move and a line
  cairo_new_path(cr);
  vibra::render::add_polygon(cr, broken);
  CHECK(path_points(cr) == 5);  // the three numbers, closed (Cairo moves to the start after a close)
}

TEST_CASE("a spring scaled to a run of 1e200 keeps its coils: lengths are taken without squaring", "[render][reach]") {
  // A run that reaches 1e200 is drawn in a world of that size, where a
  // segment's squared length overflows: the spring's direction came out NaN.
  const auto [along, across] = vibra::render::segment_axes(Point(0, 2e200), Point(3e200, 2e200));
  CHECK(along.x() == 1);
  CHECK(across.y() == 1);
  vibra::render::SpringShape shape;
  shape.width = 0.3e200, shape.lead = 0.2e200, shape.coils = 9;
  const auto points = vibra::render::spring_points(Point(0, 2e200), Point(3e200, 2e200), shape);
  REQUIRE(points.size() == 2 * 9 + 4);
  for (const Point& p : points) CHECK((std::isfinite(p.x()) && std::isfinite(p.y())));
  CHECK(points[2].y() == Approx(2.15e200));  // the first coil's peak, half the width above the axis
}
