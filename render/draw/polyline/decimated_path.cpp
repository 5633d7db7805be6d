// A curve (x(s), y(s)) thinned on a grid as it streams in, for paths that are not functions of x (orbits, phase portraits).
#include "render/draw/polyline/decimated_path.hpp"

#include <algorithm>
#include <cmath>

namespace vibra::render {

namespace {
constexpr size_t kWarmUp = 256;             ///< raw points kept before the path's size sets the grid
constexpr size_t kSegmentBudget = 1 << 19;  ///< about 20 MB with the points; then the grid coarsens
constexpr int kHalfSpan = 1 << 14;          ///< cell indices stay in (-2^14, 2^14): two fit in 32 bits
}  // namespace

DecimatedPath::DecimatedPath(int resolution) : resolution_(std::clamp(resolution, 16, kHalfSpan)) {}

bool DecimatedPath::fits_grid(const Point& p) const {
  const Point cell = (p - origin_) / cell_size_;
  return std::abs(cell.x()) < kHalfSpan - 1 && std::abs(cell.y()) < kHalfSpan - 1;
}

DecimatedPath::Cell DecimatedPath::cell_of(const Point& p) const {
  const auto index = [&](double v) { return static_cast<Cell>(static_cast<int>(std::floor(v / cell_size_)) + 2 * kHalfSpan); };
  return index(p.x() - origin_.x()) << 16 | index(p.y() - origin_.y());
}

void DecimatedPath::visit(const Point& p, bool joined) {
  const Cell cell = cell_of(p);
  if (joined && started_ && cell == last_cell_) return;
  if (joined && started_) {
    const std::uint64_t segment = std::uint64_t(std::min(cell, last_cell_)) << 32 | std::max(cell, last_cell_);
    if (segments_.insert(segment).second) {
      if (!stroke_open_) strokes_.push_back({last_point_}), stroke_open_ = true;
      strokes_.back().push_back(p);
    } else {
      stroke_open_ = false;  // retracing: the next new segment starts a new stroke
    }
  } else {
    stroke_open_ = false;
  }
  started_ = true;
  last_cell_ = cell;
  last_point_ = p;
}

// Replays the kept strokes on the current grid (after cell_size_ changed).
void DecimatedPath::regrid() {
  const Point resume = last_point_;
  std::vector<std::vector<Point>> old;
  old.swap(strokes_);
  segments_.clear();
  started_ = false;
  for (const auto& stroke : old)
    for (size_t i = 0; i < stroke.size(); ++i) visit(stroke[i], i > 0);
  visit(resume, false);  // the live path continues from where it was
}

void DecimatedPath::add(double x, double y) {
  const Point p(x, y);
  if (!std::isfinite(x) || !std::isfinite(y)) return;
  bounds_.extend(p);
  if (cell_size_ == 0) {
    if (strokes_.empty()) strokes_.emplace_back();
    if (strokes_[0].empty() || strokes_[0].back() != p) strokes_[0].push_back(p);
    const double extent = bounds_.sizes().maxCoeff();
    if (strokes_[0].size() >= kWarmUp && extent > 0) {
      origin_ = strokes_[0].front();
      cell_size_ = extent / resolution_;
      last_point_ = strokes_[0].back();
      regrid();  // replays the warm-up points on the grid
    }
    return;
  }
  while (!fits_grid(p)) {
    cell_size_ *= 2;
    regrid();
  }
  visit(p, true);
  if (segments_.size() > kSegmentBudget) {
    cell_size_ *= 2;
    regrid();
  }
}

const std::vector<std::vector<Point>>& DecimatedPath::strokes() const { return strokes_; }

}  // namespace vibra::render
