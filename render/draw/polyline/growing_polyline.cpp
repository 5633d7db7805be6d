// Draws a whole-run curve up to an instant, whole or strip by strip, as one stroke would.
#include "render/draw/polyline/growing_polyline.hpp"

#include <cairo.h>

#include <algorithm>
#include <cmath>

#include "render/draw/stroke_raster.hpp"

namespace vibra::render {

GrowingPolyline::GrowingPolyline(std::vector<Point> points) : points_(std::move(points)), length_(points_.size()) {
  // Measured as the stroke measures, so that a piece's dashes fall where the whole curve's do.
  for (size_t i = 1; i < points_.size(); ++i)
    length_[i] = length_[i - 1] + stroked_distance(points_[i - 1].x(), points_[i - 1].y(), points_[i].x(), points_[i].y());
}

int GrowingPolyline::shown(double until_x) const {
  return int(std::partition_point(points_.begin(), points_.end(), [&](const Point& p) { return p.x() <= until_x; }) -
             points_.begin());
}

std::optional<double> GrowingPolyline::last_x(double until_x) const {
  const int end = shown(until_x);
  if (end == 0) return std::nullopt;
  return points_[end - 1].x();
}

void GrowingPolyline::draw_range(Canvas& canvas, int first, int end, const std::optional<Point>& now,
                                 const Stroke& s) const {
  std::vector<Point> part(points_.begin() + first, points_.begin() + end);
  if (now && (part.empty() || now->x() > part.back().x())) part.push_back(*now);
  if (part.size() >= 2) {
    Stroke stroke = s;
    stroke.dash_offset = length_[first];
    // Round joins: a coarse run turns sharply at its mesh points, where a
    // mitre would spike past the value the scheme computed.
    cairo_set_line_join(canvas.cr(), CAIRO_LINE_JOIN_ROUND);
    draw_pixel_polyline(canvas, part, stroke);
  }
}

void GrowingPolyline::draw_until(Canvas& canvas, double until_x, const std::optional<Point>& now,
                                 const Stroke& s) const {
  draw_range(canvas, 0, shown(until_x), now, s);
}

void GrowingPolyline::draw_piece_until(Canvas& canvas, double from_x, double until_x, const std::optional<Point>& now,
                                       const Stroke& s) const {
  const int end = shown(until_x);
  const double back = from_x - reach(s.width * canvas.scale());
  // Points run left to right (a curve against time): the piece starts at the
  // last point left of `back`, so the segment crossing it is in the path.
  const auto after = std::partition_point(points_.begin(), points_.begin() + end,
                                          [&](const Point& p) { return p.x() < back; });
  const int first = std::max(0, int(after - points_.begin()) - 1);
  cairo_t* cr = canvas.cr();
  cairo_save(cr);
  cairo_rectangle(cr, from_x, 0, canvas.width() - from_x, canvas.height());
  cairo_clip(cr);
  draw_range(canvas, first, end, now, s);
  cairo_restore(cr);
}

}  // namespace vibra::render
