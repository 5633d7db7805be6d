#include "render/labels/occupancy_grid.hpp"

#include <algorithm>
#include <cmath>

namespace vibra::render {

namespace {
/// floor(v) clamped to [lo, hi] before the cast: a path far outside the
/// picture (a run leaving the view) has coordinates no int can hold.
int clamped_floor(double v, int lo, int hi) {
  if (!(v > lo)) return lo;  // NaN too
  if (v >= hi) return hi;
  return static_cast<int>(std::floor(v));
}
}  // namespace

OccupancyGrid::OccupancyGrid(const PixelRect& area, double cell, double clearance)
    : area_(area),
      cell_(std::max(1.0, cell)),
      clearance_(clearance),
      columns_(std::max(1, static_cast<int>(std::ceil(area.w / cell_)))),
      rows_(std::max(1, static_cast<int>(std::ceil(area.h / cell_)))),
      cells_(static_cast<size_t>(columns_) * rows_, 0) {}

void OccupancyGrid::mark_segment(const Point& a, const Point& b, double reach) {
  // A cell is taken when its centre lies within reach plus half its diagonal.
  const double r = reach + 0.7072 * cell_;
  const int c0 = clamped_floor((std::min(a.x(), b.x()) - r - area_.x) / cell_, 0, columns_);
  const int c1 = clamped_floor((std::max(a.x(), b.x()) + r - area_.x) / cell_, -1, columns_ - 1);
  const int r0 = clamped_floor((std::min(a.y(), b.y()) - r - area_.y) / cell_, 0, rows_);
  const int r1 = clamped_floor((std::max(a.y(), b.y()) + r - area_.y) / cell_, -1, rows_ - 1);
  for (int row = r0; row <= r1; ++row)
    for (int column = c0; column <= c1; ++column) {
      const Point centre(area_.x + (column + 0.5) * cell_, area_.y + (row + 0.5) * cell_);
      if (distance_to_segment(centre, a, b) <= r) mark(column, row);
    }
}

void OccupancyGrid::mark_polygon(const std::vector<Point>& polygon) {
  // Even-odd scanlines through the cells' centres; the edges are marked as
  // segments, so a cell the polygon only grazes is taken too.
  double top = 1e300, bottom = -1e300;
  for (const Point& p : polygon) top = std::min(top, p.y()), bottom = std::max(bottom, p.y());
  const int first = clamped_floor((top - area_.y) / cell_, 0, rows_);
  const int last = clamped_floor((bottom - area_.y) / cell_, -1, rows_ - 1);
  for (int row = first; row <= last; ++row) {
    const double y = area_.y + (row + 0.5) * cell_;
    std::vector<double> xs;
    for (size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
      const Point &p = polygon[i], &q = polygon[j];
      if ((p.y() > y) != (q.y() > y)) xs.push_back(p.x() + (y - p.y()) * (q.x() - p.x()) / (q.y() - p.y()));
    }
    std::sort(xs.begin(), xs.end());
    for (size_t k = 0; k + 1 < xs.size(); k += 2) {
      const int c0 = clamped_floor((xs[k] - area_.x) / cell_, 0, columns_);
      const int c1 = clamped_floor((xs[k + 1] - area_.x) / cell_, -1, columns_ - 1);
      for (int column = c0; column <= c1; ++column) mark(column, row);
    }
  }
}

void OccupancyGrid::add(const OutlineShape& shape) {
  const PixelRect& b = shape.bounds;
  if (b.x > area_.x + area_.w + clearance_ || b.x + b.w < area_.x - clearance_ || b.y > area_.y + area_.h + clearance_ ||
      b.y + b.h < area_.y - clearance_)
    return;
  for (const auto& [a, c] : shape.segments) mark_segment(a, c, shape.half_width + clearance_);
  for (const auto& polygon : shape.polygons) mark_polygon(polygon);
  sums_current_ = false;
}

void OccupancyGrid::add_box(const PixelRect& r) {
  Outline box;
  box.add_box(r, OutlineKind::label);
  add(box.shapes().front());
}

void OccupancyGrid::build_sums() {
  sums_.assign(static_cast<size_t>(rows_ + 1) * (columns_ + 1), 0);
  for (int row = 0; row < rows_; ++row)
    for (int column = 0; column < columns_; ++column)
      sums_[static_cast<size_t>(row + 1) * (columns_ + 1) + column + 1] =
          cells_[static_cast<size_t>(row) * columns_ + column] + sums_[static_cast<size_t>(row) * (columns_ + 1) + column + 1] +
          sums_[static_cast<size_t>(row + 1) * (columns_ + 1) + column] - sums_[static_cast<size_t>(row) * (columns_ + 1) + column];
  sums_current_ = true;
}

long long OccupancyGrid::taken(const PixelRect& r) {
  if (!sums_current_) build_sums();
  const int c0 = clamped_floor((r.x - area_.x) / cell_, 0, columns_);
  const int c1 = clamped_floor((r.x + r.w - area_.x) / cell_ + 1, 0, columns_);
  const int r0 = clamped_floor((r.y - area_.y) / cell_, 0, rows_);
  const int r1 = clamped_floor((r.y + r.h - area_.y) / cell_ + 1, 0, rows_);
  auto at = [&](int row, int column) { return sums_[static_cast<size_t>(row) * (columns_ + 1) + column]; };
  return at(r1, c1) - at(r0, c1) - at(r1, c0) + at(r0, c0);
}

}  // namespace vibra::render
