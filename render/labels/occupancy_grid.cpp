// OccupancyGrid: a drawing's outline rasterized into cells with a summed-area table, to test whether a box is free.
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

namespace {
/// Storage of grids that are gone, for the next grid in this thread.
thread_local std::vector<std::vector<unsigned char>> spare_cells;
thread_local std::vector<std::vector<int>> spare_sums;
}  // namespace

OccupancyGrid::OccupancyGrid(const PixelRect& area, double cell, double clearance)
    : area_(area),
      cell_(std::max(1.0, cell)),
      clearance_(clearance),
      columns_(std::max(1, static_cast<int>(std::ceil(area.w / cell_)))),
      rows_(std::max(1, static_cast<int>(std::ceil(area.h / cell_)))) {
  if (!spare_cells.empty()) buffers_.cells = std::move(spare_cells.back()), spare_cells.pop_back();
  if (!spare_sums.empty()) buffers_.sums = std::move(spare_sums.back()), spare_sums.pop_back();
  buffers_.cells.assign(static_cast<size_t>(columns_) * rows_, 0);
}

OccupancyGrid::~OccupancyGrid() {
  constexpr size_t kKept = 4;  // grids alive at once in one thread, at most
  if (spare_cells.size() < kKept) spare_cells.push_back(std::move(buffers_.cells));
  if (spare_sums.size() < kKept) spare_sums.push_back(std::move(buffers_.sums));
}

OccupancyGrid::CellRange OccupancyGrid::cells_of(const PixelRect& r) const {
  return {clamped_floor((r.x - area_.x) / cell_, 0, columns_), clamped_floor((r.x + r.w - area_.x) / cell_, -1, columns_ - 1),
          clamped_floor((r.y - area_.y) / cell_, 0, rows_), clamped_floor((r.y + r.h - area_.y) / cell_, -1, rows_ - 1)};
}

namespace {
/// Narrows [lo, hi] to the x where k x + m >= 0 (a half-line, all or nothing when k = 0).
void keep_where_nonnegative(double k, double m, double& lo, double& hi) {
  if (k > 0) lo = std::max(lo, -m / k);
  else if (k < 0) hi = std::min(hi, -m / k);
  else if (m < 0) lo = 1, hi = 0;
}

/// The x where the line y meets the disk of radius r around c, widening [lo, hi].
void widen_by_disk(const Point& c, double r, double y, double& lo, double& hi) {
  const double dy = y - c.y(), h2 = r * r - dy * dy;
  if (h2 < 0) return;
  const double h = std::sqrt(h2);
  lo = std::min(lo, c.x() - h), hi = std::max(hi, c.x() + h);
}
}  // namespace

void OccupancyGrid::mark_segment(const Point& a, const Point& b, double reach) {
  // A cell is taken when its centre lies within reach plus half its diagonal
  // of the segment: on each row of centres that is one interval of x (the
  // row's line through the capsule around the segment), found in closed
  // form rather than by measuring every cell.
  const double r = reach + 0.7072 * cell_;
  const int r0 = clamped_floor((std::min(a.y(), b.y()) - r - area_.y) / cell_, 0, rows_);
  const int r1 = clamped_floor((std::max(a.y(), b.y()) + r - area_.y) / cell_, -1, rows_ - 1);
  const Point d = b - a;
  const double length = d.norm();
  for (int row = r0; row <= r1; ++row) {
    const double y = area_.y + (row + 0.5) * cell_;
    double lo = INFINITY, hi = -INFINITY;
    widen_by_disk(a, r, y, lo, hi);
    widen_by_disk(b, r, y, lo, hi);
    if (length > 0) {
      // The band: 0 <= t(x) <= 1 along the segment, |distance across| <= r.
      double band_lo = -INFINITY, band_hi = INFINITY;
      const double ey = y - a.y();
      keep_where_nonnegative(d.x(), ey * d.y() - a.x() * d.x(), band_lo, band_hi);  // t >= 0 (times length^2)
      keep_where_nonnegative(-d.x(), length * length - ey * d.y() + a.x() * d.x(), band_lo, band_hi);  // t <= 1
      const double across0 = -a.x() * d.y() - ey * d.x();  // (x - ax) dy - ey dx = x dy + across0
      keep_where_nonnegative(d.y(), across0 + r * length, band_lo, band_hi);
      keep_where_nonnegative(-d.y(), r * length - across0, band_lo, band_hi);
      if (band_lo <= band_hi) lo = std::min(lo, band_lo), hi = std::max(hi, band_hi);
    }
    if (!(lo <= hi)) continue;
    // Columns whose centre x = area.x + (column + 0.5) cell lies in [lo, hi].
    const int c0 = clamped_floor(std::ceil((lo - area_.x) / cell_ - 0.5), 0, columns_);
    const int c1 = clamped_floor((hi - area_.x) / cell_ - 0.5, -1, columns_ - 1);
    for (int column = c0; column <= c1; ++column) mark(column, row);
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
  // Skipped when out of every cell's reach (mark_segment's: the clearance and half a cell's diagonal).
  const PixelRect& b = shape.bounds;
  const double reach = clearance_ + 0.7072 * cell_;
  if (b.x > area_.x + area_.w + reach || b.x + b.w < area_.x - reach || b.y > area_.y + area_.h + reach ||
      b.y + b.h < area_.y - reach)
    return;
  for (const auto& [a, c] : shape.segments) mark_segment(a, c, shape.half_width + clearance_);
  for (const auto& polygon : shape.polygons) mark_polygon(polygon);
  sums_current_ = false;
}

void OccupancyGrid::add_box(const PixelRect& r) {
  const CellRange range = cells_of({r.x - clearance_, r.y - clearance_, r.w + 2 * clearance_, r.h + 2 * clearance_});
  if (range.c0 <= range.c1 && range.r0 <= range.r1) boxes_.push_back(range);
}

void OccupancyGrid::build_sums() {
  const size_t stride = static_cast<size_t>(columns_) + 1;
  std::vector<int>& sums = buffers_.sums;
  sums.resize(static_cast<size_t>(rows_ + 1) * stride);
  std::fill(sums.begin(), sums.begin() + static_cast<std::ptrdiff_t>(stride), 0);  // row 0
  const unsigned char* cells = buffers_.cells.data();
  for (int row = 0; row < rows_; ++row) {
    int* above = sums.data() + static_cast<size_t>(row) * stride;
    int* here = above + stride;
    here[0] = 0;
    int along = 0;  // this row's cells so far
    for (int column = 0; column < columns_; ++column) {
      along += cells[static_cast<size_t>(row) * columns_ + column];
      here[column + 1] = above[column + 1] + along;
    }
  }
  sums_current_ = true;
}

long long OccupancyGrid::taken(const PixelRect& r) {
  if (!sums_current_) build_sums();
  const int c0 = clamped_floor((r.x - area_.x) / cell_, 0, columns_);
  const int c1 = clamped_floor((r.x + r.w - area_.x) / cell_ + 1, 0, columns_);
  const int r0 = clamped_floor((r.y - area_.y) / cell_, 0, rows_);
  const int r1 = clamped_floor((r.y + r.h - area_.y) / cell_ + 1, 0, rows_);
  const size_t stride = static_cast<size_t>(columns_) + 1;
  auto at = [&](int row, int column) { return static_cast<long long>(buffers_.sums[static_cast<size_t>(row) * stride + column]); };
  long long count = at(r1, c1) - at(r0, c1) - at(r1, c0) + at(r0, c0);
  // The query covers columns c0 .. c1 - 1 and rows r0 .. r1 - 1.
  for (const CellRange& b : boxes_) {
    const long long across = std::min(c1 - 1, b.c1) - std::max(c0, b.c0) + 1;
    const long long down = std::min(r1 - 1, b.r1) - std::max(r0, b.r0) + 1;
    if (across > 0 && down > 0) count += across * down;
  }
  return count;
}

}  // namespace vibra::render
