// The browser build's Cairo paths: kept in device pixels with arcs flattened into lines, and handed on as they are built.
#include <algorithm>
#include <cmath>
#include <limits>

#include "web/shim/cairo_context.hpp"

namespace {

using vibra::web::shim::commands;
using vibra::web::shim::DevicePoint;

/// Arcs are flattened to within this many device pixels, as Cairo's default tolerance.
constexpr double kTolerance = 0.1;
/// The most segments of one arc, however large its radius.
constexpr int kMostArcSegments = 1024;

void add_move(cairo_t* cr, DevicePoint p) {
  cr->path.push_back({{p}, false});
  cr->has_current_point = true;
  cr->current = p;
  commands(cr).move_to(p.x, p.y);
}

void add_line(cairo_t* cr, DevicePoint p) {
  if (!cr->has_current_point || cr->path.empty()) return add_move(cr, p);
  cr->path.back().points.push_back(p);
  cr->current = p;
  commands(cr).line_to(p.x, p.y);
}

/// How many segments an arc of `sweep` radians needs: its radius measured
/// in device pixels along the user matrix's larger axis.
int arc_segments(const cairo_t* cr, double radius, double sweep) {
  const auto& m = cr->state.pen.matrix;
  const double scale = std::max(std::hypot(m[0], m[1]), std::hypot(m[2], m[3]));
  const double r = radius * scale;
  if (r <= kTolerance) return 1;
  const double step = 2 * std::acos(1 - kTolerance / r);
  return std::clamp(static_cast<int>(std::ceil(std::abs(sweep) / step)), 1, kMostArcSegments);
}

void add_arc(cairo_t* cr, double xc, double yc, double radius, double a1, double a2) {
  const int n = arc_segments(cr, radius, a2 - a1);
  for (int k = 0; k <= n; ++k) {
    const double a = a1 + (a2 - a1) * k / n;
    add_line(cr, vibra::web::shim::to_device(cr, xc + radius * std::cos(a), yc + radius * std::sin(a)));
  }
}

}  // namespace

extern "C" {

void cairo_new_path(cairo_t* cr) {
  cr->path.clear();
  cr->path_text.clear();
  cr->has_current_point = false;
  commands(cr).begin_path();
}

void cairo_new_sub_path(cairo_t* cr) { cr->has_current_point = false; }
void cairo_move_to(cairo_t* cr, double x, double y) { add_move(cr, vibra::web::shim::to_device(cr, x, y)); }
void cairo_line_to(cairo_t* cr, double x, double y) { add_line(cr, vibra::web::shim::to_device(cr, x, y)); }

void cairo_close_path(cairo_t* cr) {
  if (!cr->has_current_point || cr->path.empty()) return;
  cr->path.back().closed = true;
  cr->current = cr->path.back().points.front();
  commands(cr).close_path();
  // As in Cairo, a line after the close starts from the subpath's first point.
  cr->path.push_back({{cr->current}, false});
}

void cairo_rectangle(cairo_t* cr, double x, double y, double width, double height) {
  cairo_move_to(cr, x, y);
  cairo_line_to(cr, x + width, y);
  cairo_line_to(cr, x + width, y + height);
  cairo_line_to(cr, x, y + height);
  cairo_close_path(cr);
}

void cairo_arc(cairo_t* cr, double xc, double yc, double radius, double a1, double a2) {
  while (a2 < a1) a2 += 2 * M_PI;  // Cairo's rule: the arc runs forward from a1
  add_arc(cr, xc, yc, radius, a1, a2);
}

void cairo_arc_negative(cairo_t* cr, double xc, double yc, double radius, double a1, double a2) {
  while (a2 > a1) a2 -= 2 * M_PI;
  add_arc(cr, xc, yc, radius, a1, a2);
}

void cairo_path_extents(cairo_t* cr, double* x1, double* y1, double* x2, double* y2) {
  double box[4] = {std::numeric_limits<double>::max(), std::numeric_limits<double>::max(),
                   std::numeric_limits<double>::lowest(), std::numeric_limits<double>::lowest()};
  for (const auto& sub : cr->path)
    for (const DevicePoint& d : sub.points) {
      const DevicePoint p = vibra::web::shim::to_user(cr, d.x, d.y);
      box[0] = std::min(box[0], p.x), box[1] = std::min(box[1], p.y);
      box[2] = std::max(box[2], p.x), box[3] = std::max(box[3], p.y);
    }
  if (box[0] > box[2]) box[0] = box[1] = box[2] = box[3] = 0;  // no path: Cairo's empty extents
  *x1 = box[0], *y1 = box[1], *x2 = box[2], *y2 = box[3];
}

cairo_path_t* cairo_copy_path_flat(cairo_t* cr) {
  auto* path = new cairo_path_t{CAIRO_STATUS_SUCCESS, nullptr, 0};
  std::vector<cairo_path_data_t> data;
  auto element = [&](cairo_path_data_type_t type, const DevicePoint* d) {
    cairo_path_data_t header{};
    header.header = {type, d ? 2 : 1};
    data.push_back(header);
    if (!d) return;
    cairo_path_data_t point{};
    const DevicePoint p = vibra::web::shim::to_user(cr, d->x, d->y);
    point.point = {p.x, p.y};
    data.push_back(point);
  };
  for (const auto& sub : cr->path) {
    for (std::size_t i = 0; i < sub.points.size(); ++i)
      element(i == 0 ? CAIRO_PATH_MOVE_TO : CAIRO_PATH_LINE_TO, &sub.points[i]);
    if (sub.closed) element(CAIRO_PATH_CLOSE_PATH, nullptr);
  }
  path->num_data = static_cast<int>(data.size());
  path->data = new cairo_path_data_t[data.size() + 1];
  std::copy(data.begin(), data.end(), path->data);
  return path;
}

void cairo_path_destroy(cairo_path_t* path) {
  if (!path) return;
  delete[] path->data;
  delete path;
}

}  // extern "C"
