#include "render/draw/growing_polyline.hpp"

#include <cairo.h>

#include <algorithm>
#include <cmath>

#include "render/draw/stroke_raster.hpp"

namespace vibra::render {

GrowingPolyline::GrowingPolyline(std::vector<Point> points, std::vector<int> ends)
    : points_(std::move(points)), length_(points_.size()), ends_(std::move(ends)) {
  // Measured as the stroke measures, so that a piece's dashes fall where the whole curve's do.
  for (size_t i = 1; i < points_.size(); ++i)
    length_[i] = length_[i - 1] + stroked_distance(points_[i - 1].x(), points_[i - 1].y(), points_[i].x(), points_[i].y());
}

int GrowingPolyline::end_of(int last_column) const {
  if (ends_.empty() || last_column < 0) return 0;
  return ends_[std::min<size_t>(last_column, ends_.size() - 1)];
}

std::optional<double> GrowingPolyline::last_x(int last_column) const {
  const int end = end_of(last_column);
  if (end == 0) return std::nullopt;
  return points_[end - 1].x();
}

void GrowingPolyline::stroke_range(Canvas& canvas, int first, int end, const Stroke& s) const {
  if (end - first < 2) return;
  Stroke stroke = s;
  stroke.dash_offset = length_[first];
  std::vector<Point> part(points_.begin() + first, points_.begin() + end);
  draw_pixel_polyline(canvas, part, stroke);
}

void GrowingPolyline::draw_through(Canvas& canvas, int last_column, const Stroke& s) const {
  stroke_range(canvas, 0, end_of(last_column), s);
}

void GrowingPolyline::draw_piece(Canvas& canvas, double from_x, int last_column, const Stroke& s) const {
  const int end = end_of(last_column);
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
  stroke_range(canvas, first, end, s);
  cairo_restore(cr);
}

}  // namespace vibra::render
