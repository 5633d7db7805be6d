// The browser build's Cairo drawing: stroke, fill, clip and paint handed on as 2D-canvas operations.
#include <algorithm>
#include <array>
#include <limits>

#include "web/shim/cairo_context.hpp"

namespace {

using vibra::web::shim::commands;

/// A surface as the source of a stroke or paint: the 2D canvas is not
/// handed it (no scene strokes or paints with one in the browser); counted,
/// so that tests see it.
bool skipped(cairo_t* cr) {
  if (cr->state.source.type != CAIRO_PATTERN_TYPE_SURFACE) return false;
  ++cr->target->skipped;
  return true;
}

using Matrix = std::array<double, 6>;  // xx yx xy yy x0 y0, as cairo_matrix_t

/// a after b.
Matrix after(const Matrix& a, const Matrix& b) {
  return {a[0] * b[0] + a[2] * b[1], a[1] * b[0] + a[3] * b[1], a[0] * b[2] + a[2] * b[3],
          a[1] * b[2] + a[3] * b[3], a[0] * b[4] + a[2] * b[5] + a[4], a[1] * b[4] + a[3] * b[5] + a[5]};
}

Matrix inverse(const Matrix& m) {
  const double det = m[0] * m[3] - m[1] * m[2];
  return {m[3] / det, -m[1] / det, -m[2] / det, m[0] / det, (m[2] * m[5] - m[3] * m[4]) / det,
          (m[1] * m[4] - m[0] * m[5]) / det};
}

/// The path filled with the source surface as Cairo fills it: the surface's
/// own drawing as a tile, repeated or once, its pixels taken to the page
/// through the pattern's matrix and the user space it was set in.
void fill_with_surface(cairo_t* cr) {
  const _cairo_pattern& p = cr->state.source;
  const Matrix to_page = after(cr->state.source_user, inverse(p.matrix));
  const bool smooth = p.filter != CAIRO_FILTER_NEAREST && p.filter != CAIRO_FILTER_FAST;
  commands(cr).fill_pattern(p.surface->commands, p.surface->width, p.surface->height, to_page,
                            p.extend == CAIRO_EXTEND_REPEAT, smooth, false);
}

/// The text runs laid on the path, stroked or filled with the pen.
void draw_path_text(cairo_t* cr, bool stroked) {
  for (const auto& run : cr->path_text) {
    vibra::web::Pen pen = cr->state.pen;
    pen.matrix = run.matrix;
    commands(cr).text(stroked, pen, run.x, run.y, run.font, run.text);
  }
}

void fill(cairo_t* cr, bool preserve) {
  if (cr->state.source.type == CAIRO_PATTERN_TYPE_SURFACE) {
    fill_with_surface(cr);
  } else {
    commands(cr).fill(cr->state.pen.rgba, false);
    draw_path_text(cr, false);
  }
  if (!preserve) cairo_new_path(cr);
}

/// The device box of the current path.
std::array<double, 4> path_box(const cairo_t* cr) {
  std::array<double, 4> box{std::numeric_limits<double>::max(), std::numeric_limits<double>::max(),
                            std::numeric_limits<double>::lowest(), std::numeric_limits<double>::lowest()};
  for (const auto& sub : cr->path)
    for (const auto& p : sub.points) {
      box[0] = std::min(box[0], p.x), box[1] = std::min(box[1], p.y);
      box[2] = std::max(box[2], p.x), box[3] = std::max(box[3], p.y);
    }
  return box;
}

}  // namespace

extern "C" {

void cairo_stroke(cairo_t* cr) {
  if (!skipped(cr)) {
    commands(cr).stroke(cr->state.pen);
    draw_path_text(cr, true);
  }
  cairo_new_path(cr);
}

void cairo_fill(cairo_t* cr) { fill(cr, false); }
void cairo_fill_preserve(cairo_t* cr) { fill(cr, true); }

void cairo_clip(cairo_t* cr) {
  // The clip's box is kept for cairo_clip_extents: the path's bounding box,
  // exact for the rectangles the scene code clips to.
  const auto box = path_box(cr);
  auto& clip = cr->state.clip;
  clip = {std::max(clip[0], box[0]), std::max(clip[1], box[1]), std::min(clip[2], box[2]), std::min(clip[3], box[3])};
  commands(cr).clip(false);
  cairo_new_path(cr);
}

void cairo_clip_extents(cairo_t* cr, double* x1, double* y1, double* x2, double* y2) {
  const auto& c = cr->state.clip;
  const double w = cr->target->width, h = cr->target->height;
  const auto a = vibra::web::shim::to_user(cr, std::max(c[0], 0.0), std::max(c[1], 0.0));
  const auto b = vibra::web::shim::to_user(cr, std::min(c[2], w), std::min(c[3], h));
  *x1 = std::min(a.x, b.x), *y1 = std::min(a.y, b.y), *x2 = std::max(a.x, b.x), *y2 = std::max(a.y, b.y);
}

cairo_rectangle_list_t* cairo_copy_clip_rectangle_list(cairo_t* cr) {
  double x1, y1, x2, y2;
  cairo_clip_extents(cr, &x1, &y1, &x2, &y2);
  return new cairo_rectangle_list_t{CAIRO_STATUS_SUCCESS, new cairo_rectangle_t{x1, y1, x2 - x1, y2 - y1}, 1};
}

void cairo_rectangle_list_destroy(cairo_rectangle_list_t* list) {
  if (!list) return;
  delete list->rectangles;
  delete list;
}

void cairo_paint_with_alpha(cairo_t* cr, double alpha) {
  if (cr->state.group_source) {
    commands(cr).pop_group_paint(alpha);
    cr->state.group_source = false;
    return;
  }
  if (skipped(cr)) return;
  auto rgba = cr->state.pen.rgba;
  rgba[3] *= alpha;
  commands(cr).paint(rgba);
}

void cairo_paint(cairo_t* cr) { cairo_paint_with_alpha(cr, 1); }

}  // extern "C"
