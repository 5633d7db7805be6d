#include "render/trail.hpp"

#include <algorithm>
#include <cmath>

#include "render/shapes.hpp"

namespace vibra::render {

Trail::Trail(double spacing, size_t budget) : spacing_(spacing), budget_(std::max<size_t>(budget, 16)) {}

void Trail::add(double t, const Point& p) {
  if (!std::isfinite(p.x()) || !std::isfinite(p.y())) return;
  if (!points_.empty() && (p - points_.back().p).norm() < spacing_) return;
  points_.push_back({t, p});
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

void Trail::draw(Canvas& canvas, const WorldView& view, double t, double fade, const Color& color, double width) const {
  if (!(fade > 0)) return;
  auto by_time = [](const Stamped& s, double x) { return s.t < x; };
  auto first = std::lower_bound(points_.begin(), points_.end(), t - fade, by_time);
  auto last = std::upper_bound(points_.begin(), points_.end(), t, [](double x, const Stamped& s) { return x < s.t; });
  if (last - first < 2) return;
  // Chunks of a few segments share one opacity: the fade looks continuous
  // and the stroke count stays small.
  constexpr long kChunk = 8;
  std::vector<Point> pixels;
  for (auto start = first; start + 1 < last; start += kChunk) {
    const auto end = std::min(start + kChunk, last - 1);
    const double age = (t - start->t) / fade;
    pixels.clear();
    for (auto it = start; it <= end; ++it) pixels.push_back(view.to_pixel(it->p));
    draw_pixel_polyline(canvas, pixels, {color.with_alpha(std::clamp(1 - age, 0.0, 1.0) * 0.8), width});
  }
}

}  // namespace vibra::render
