// Damage tracking: the pixel rectangles a frame changed, so the next frame restores its background only there.
#include "render/draw/damage.hpp"

#include <algorithm>
#include <cmath>

namespace vibra::render {

void Damage::add(double x0, double y0, double x1, double y1, double margin) {
  if (all_) return;
  if (!std::isfinite(x0) || !std::isfinite(y0) || !std::isfinite(x1) || !std::isfinite(y1)) {
    all_ = true;  // cannot tell where: say everywhere
    return;
  }
  // Clamped as doubles first: a far-off box must not overflow an int.
  const auto to_x = [&](double x) { return static_cast<int>(std::clamp(x, 0.0, double(width_))); };
  const auto to_y = [&](double y) { return static_cast<int>(std::clamp(y, 0.0, double(height_))); };
  const DamageRect r{to_x(std::floor(std::min(x0, x1) - margin)), to_y(std::floor(std::min(y0, y1) - margin)),
                     to_x(std::ceil(std::max(x0, x1) + margin)), to_y(std::ceil(std::max(y0, y1) + margin))};
  if (r.x0 >= r.x1 || r.y0 >= r.y1) return;  // off the picture
  rects_.push_back(r);
}

void Damage::add(const Damage& other) {
  if (other.all_) all_ = true;
  if (all_) return;
  rects_.insert(rects_.end(), other.rects_.begin(), other.rects_.end());
}

bool Damage::intersects(int x0, int y0, int x1, int y1) const {
  if (all_) return true;
  return std::any_of(rects_.begin(), rects_.end(),
                     [&](const DamageRect& r) { return r.x0 < x1 && x0 < r.x1 && r.y0 < y1 && y0 < r.y1; });
}

void Damage::spans(int y0, int y1, std::vector<std::pair<int, int>>& spans) const {
  spans.clear();
  if (all_) {
    spans.emplace_back(0, width_);
    return;
  }
  for (const DamageRect& r : rects_)
    if (r.y0 < y1 && y0 < r.y1) spans.emplace_back(r.x0, r.x1);
  std::sort(spans.begin(), spans.end());
  std::size_t kept = 0;
  for (const auto& span : spans) {
    if (kept > 0 && span.first <= spans[kept - 1].second)
      spans[kept - 1].second = std::max(spans[kept - 1].second, span.second);
    else
      spans[kept++] = span;
  }
  spans.resize(kept);
}

}  // namespace vibra::render
