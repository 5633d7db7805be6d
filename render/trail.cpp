#include "render/trail.hpp"

#include <algorithm>
#include <cmath>

#include "render/shapes.hpp"

namespace vibra::render {

namespace {
/// How far a dropped point may lie from the segment drawn in its place, in pixels.
constexpr double kTolerancePixels = 0.25;

/// The points a polyline within `tolerance` of every one of `in` needs, in
/// one pass: from the last kept point (the anchor), each later point narrows
/// the wedge of directions whose ray passes within `tolerance` of it; the
/// point that leaves the wedge, or turns back towards the anchor, ends the
/// segment at the point before it.
std::vector<Trail::Stamped> simplified(const std::vector<Trail::Stamped>& in, double tolerance) {
  if (in.size() <= 2) return in;
  std::vector<Trail::Stamped> out{in.front()};
  size_t anchor = 0, last = 0;
  Point direction = Point::Zero();
  bool aimed = false;
  double lo = 0, hi = 0, reach = 0;
  auto narrow = [&](size_t i) {  // false: point i does not fit the current segment
    const Point d = in[i].p - in[anchor].p;
    const double length = d.norm();
    if (length <= tolerance) return true;  // near the anchor: any segment from it passes near enough
    const double half = std::asin(std::min(1.0, tolerance / length));
    if (!aimed) {
      direction = d / length, lo = -half, hi = half, reach = length, aimed = true;
      return true;
    }
    const double angle = std::atan2(direction.x() * d.y() - direction.y() * d.x(), direction.dot(d));
    if (angle < lo || angle > hi || length < reach - tolerance) return false;
    lo = std::max(lo, angle - half), hi = std::min(hi, angle + half), reach = std::max(reach, length);
    return true;
  };
  for (size_t i = 1; i < in.size(); ++i) {
    if (!narrow(i)) {
      out.push_back(in[last]);
      anchor = last, aimed = false;
      narrow(i);  // from the new anchor, the next point always fits
    }
    last = i;
  }
  out.push_back(in.back());
  return out;
}
}  // namespace

Trail::Trail(double spacing, size_t budget) : spacing_(spacing), budget_(std::max<size_t>(budget, 16)) {}

void Trail::add(double t, const Point& p) {
  if (!std::isfinite(p.x()) || !std::isfinite(p.y())) return;
  if (!points_.empty() && (p - points_.back().p).norm() < spacing_) return;
  points_.push_back({t, p});
  ++version_;
  if (points_.size() <= budget_) return;
  // Too many: coarsen the whole path, so memory stays flat over any run.
  spacing_ *= 2;
  std::vector<Stamped> kept;
  kept.reserve(points_.size() / 2 + 1);
  for (const Stamped& s : points_)
    if (kept.empty() || (s.p - kept.back().p).norm() >= spacing_) kept.push_back(s);
  points_.swap(kept);
}

std::vector<Point> Trail::between(double from, double to) const {
  auto by_time = [](const Stamped& s, double t) { return s.t < t; };
  auto first = std::lower_bound(points_.begin(), points_.end(), from, by_time);
  auto last = std::upper_bound(points_.begin(), points_.end(), to, [](double t, const Stamped& s) { return t < s.t; });
  std::vector<Point> out;
  for (auto it = first; it < last; ++it) out.push_back(it->p);
  return out;
}

const std::vector<Trail::Stamped>& Trail::drawn_points(double zoom) const {
  if (drawn_version_ != version_ || drawn_zoom_ != zoom) {
    drawn_ = simplified(points_, kTolerancePixels / zoom);
    drawn_zoom_ = zoom, drawn_version_ = version_;
  }
  return drawn_;
}

void Trail::draw(Canvas& canvas, const WorldView& view, double t, double fade, const Color& color, double width,
                 const std::optional<Point>& head) const {
  if (!(fade > 0)) return;
  const std::vector<Stamped>& points = drawn_points(view.zoom());
  auto by_time = [](const Stamped& s, double x) { return s.t < x; };
  auto first = std::lower_bound(points.begin(), points.end(), t - fade, by_time);
  auto last = std::upper_bound(points.begin(), points.end(), t, [](double x, const Stamped& s) { return x < s.t; });
  std::vector<Point> pixels;
  std::vector<double> opacity;
  for (auto it = first; it < last; ++it) {
    pixels.push_back(view.to_pixel(it->p));
    opacity.push_back(std::clamp(1 - (t - it->t) / fade, 0.0, 1.0) * 0.8);
  }
  if (head && std::isfinite(head->x()) && std::isfinite(head->y())) {
    pixels.push_back(view.to_pixel(*head));
    opacity.push_back(0.8);
  }
  // Runs of segments whose opacity differs by little share one stroke: the
  // fade looks continuous and the stroke count stays small whatever the
  // number of points.
  constexpr double kOpacityStep = 0.02;
  std::vector<Point> run;
  for (size_t start = 0; start + 1 < pixels.size();) {
    size_t end = start + 1;
    while (end + 1 < pixels.size() && std::abs(opacity[end + 1] - opacity[start]) < kOpacityStep) ++end;
    run.assign(pixels.begin() + long(start), pixels.begin() + long(end) + 1);
    draw_pixel_polyline(canvas, run, {color.with_alpha(0.5 * (opacity[start] + opacity[end])), width});
    start = end;
  }
}

}  // namespace vibra::render
