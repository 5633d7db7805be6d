// The browser build's Cairo: a small drawing recorded as the exact 2D-canvas operations the page replays.
#include <cairo.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <memory>

#include "shim_recording.hpp"
#include "web/canvas/surface_commands.hpp"

using vibra::web::test::Recording;
using vibra::web::test::recording;

namespace {

std::string drawn(const Recording& r) { return vibra::web::describe(vibra::web::commands_of(r.surface.get())); }

}  // namespace

TEST_CASE("a filled rectangle and a dashed line under a translation are recorded in device pixels", "[web-backend]") {
  const Recording r = recording(100, 50);
  cairo_t* cr = r.cr.get();
  cairo_set_source_rgba(cr, 1, 0, 0, 0.5);
  cairo_rectangle(cr, 10, 20, 30, 5);
  cairo_fill(cr);
  cairo_translate(cr, 5, 7);
  cairo_move_to(cr, 0, 0);
  cairo_line_to(cr, 10, 0);
  const double dashes[] = {4, 2};
  cairo_set_dash(cr, dashes, 2, 1);
  cairo_set_line_width(cr, 3);
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
  cairo_set_source_rgb(cr, 0, 0, 1);
  cairo_stroke(cr);
  CHECK(drawn(r) ==
        "moveTo 10 20\nlineTo 40 20\nlineTo 40 25\nlineTo 10 25\nclosePath\n"
        "fill 1 0 0 0.5 0\nbeginPath\n"
        "moveTo 5 7\nlineTo 15 7\n"
        "stroke 0 0 1 1 3 0 1 1 0 0 1 5 7 2 1 4 2\nbeginPath\n");
}

TEST_CASE("an arc is flattened within a tenth of a pixel of its circle", "[web-backend]") {
  const Recording r = recording(200, 200);
  cairo_t* cr = r.cr.get();
  cairo_arc(cr, 100, 100, 40, 0, 2 * M_PI);
  std::unique_ptr<cairo_path_t, void (*)(cairo_path_t*)> path(cairo_copy_path_flat(cr), cairo_path_destroy);
  int points = 0;
  double worst = 0;
  for (int i = 0; i < path->num_data; i += path->data[i].header.length) {
    if (path->data[i].header.type == CAIRO_PATH_CLOSE_PATH) continue;
    const auto& p = path->data[i + 1].point;
    worst = std::max(worst, std::abs(std::hypot(p.x - 100, p.y - 100) - 40));
    ++points;
    if (i + path->data[i].header.length < path->num_data) {  // the chord's middle, too
      const auto& q = path->data[i + path->data[i].header.length + 1].point;
      worst = std::max(worst, std::abs(std::hypot((p.x + q.x) / 2 - 100, (p.y + q.y) / 2 - 100) - 40));
    }
  }
  CHECK(points > 20);
  CHECK(points < 100);
  CHECK(worst <= 0.1);
}

TEST_CASE("paths are copied and measured in user units under a scaled matrix", "[web-backend]") {
  const Recording r = recording(100, 100);
  cairo_t* cr = r.cr.get();
  cairo_translate(cr, 10, 10);
  cairo_move_to(cr, 1, 2);
  cairo_line_to(cr, 4, 6);
  double x0, y0, x1, y1;
  cairo_path_extents(cr, &x0, &y0, &x1, &y1);
  CHECK((x0 == 1 && y0 == 2 && x1 == 4 && y1 == 6));
  double x = 1, y = 2;
  cairo_user_to_device(cr, &x, &y);
  CHECK((x == 11 && y == 12));
  CHECK(drawn(r) == "moveTo 11 12\nlineTo 14 16\n");
}

TEST_CASE("a clip bounds the clip extents and is restored with the state", "[web-backend]") {
  const Recording r = recording(100, 80);
  cairo_t* cr = r.cr.get();
  cairo_save(cr);
  cairo_rectangle(cr, 10, 20, 30, 40);
  cairo_clip(cr);
  double x0, y0, x1, y1;
  cairo_clip_extents(cr, &x0, &y0, &x1, &y1);
  CHECK((x0 == 10 && y0 == 20 && x1 == 40 && y1 == 60));
  cairo_restore(cr);
  cairo_clip_extents(cr, &x0, &y0, &x1, &y1);
  CHECK((x0 == 0 && y0 == 0 && x1 == 100 && y1 == 80));
  CHECK(drawn(r).find("clip 0\nbeginPath\nrestore\n") != std::string::npos);
}

TEST_CASE("a group is a layer painted at its alpha, and a surface source is counted, not drawn", "[web-backend]") {
  const Recording r = recording(10, 10);
  cairo_t* cr = r.cr.get();
  cairo_push_group(cr);
  cairo_set_source_rgb(cr, 0, 1, 0);
  cairo_paint(cr);
  cairo_pop_group_to_source(cr);
  cairo_paint_with_alpha(cr, 0.25);
  CHECK(drawn(r) == "pushGroup\npaint 0 1 0 1\npopGroupPaint 0.25\n");
  std::shared_ptr<cairo_surface_t> tile(cairo_image_surface_create(CAIRO_FORMAT_ARGB32, 4, 4), cairo_surface_destroy);
  cairo_set_source_surface(cr, tile.get(), 0, 0);
  cairo_paint(cr);
  CHECK(vibra::web::skipped_of(r.surface.get()) == 1);
  CHECK(cairo_surface_get_type(r.surface.get()) == CAIRO_SURFACE_TYPE_RECORDING);
}

TEST_CASE("a fill with a surface pattern carries the surface's own drawing as a tile, placed as Cairo places it",
          "[web-backend]") {
  const Recording r = recording(40, 20);
  cairo_t* cr = r.cr.get();
  std::shared_ptr<cairo_surface_t> tile(cairo_image_surface_create(CAIRO_FORMAT_ARGB32, 4, 4), cairo_surface_destroy);
  std::shared_ptr<cairo_t> tile_cr(cairo_create(tile.get()), cairo_destroy);
  cairo_set_source_rgb(tile_cr.get(), 0, 0, 1);
  cairo_paint(tile_cr.get());
  cairo_pattern_t* pattern = cairo_pattern_create_for_surface(tile.get());
  cairo_pattern_set_extend(pattern, CAIRO_EXTEND_REPEAT);
  cairo_pattern_set_filter(pattern, CAIRO_FILTER_NEAREST);
  cairo_matrix_t to_pattern;
  cairo_matrix_init_translate(&to_pattern, 3, 0);  // user (3, 0) is the tile's (0, 0)
  cairo_pattern_set_matrix(pattern, &to_pattern);
  cairo_translate(cr, 10, 0);
  cairo_set_source(cr, pattern);  // locked to this user space: the tile's origin at device (7, 0)
  cairo_translate(cr, 5, 5);      // a later transform moves the path, not the pattern
  cairo_rectangle(cr, 0, 0, 2, 2);
  cairo_fill(cr);
  cairo_pattern_destroy(pattern);
  CHECK(drawn(r) ==
        "moveTo 15 5\nlineTo 17 5\nlineTo 17 7\nlineTo 15 7\nclosePath\n"
        "fillPattern 4 4 1 0 1 0 0 1 7 0 0 5 0 0\n  paint 0 0 1 1\nbeginPath\n");
  CHECK(vibra::web::skipped_of(r.surface.get()) == 0);
}
