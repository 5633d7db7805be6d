// OccupancyGrid: a drawing's outline rasterized into cells, one bit each, to test whether a box is free.
#include "render/labels/occupancy_grid.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <stdexcept>

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
thread_local std::vector<std::vector<std::uint64_t>> spare_bits;

/// Bits [first, last) of a 64-bit word, 0 <= first < last <= 64.
std::uint64_t bits_between(int first, int last) {
  const std::uint64_t below_last = last == 64 ? ~std::uint64_t(0) : (std::uint64_t(1) << last) - 1;
  return below_last & ~((std::uint64_t(1) << first) - 1);
}
}  // namespace

OccupancyGrid::OccupancyGrid(const PixelRect& area, double cell, double clearance)
    : area_(area),
      cell_(std::max(1.0, cell)),
      clearance_(clearance),
      columns_(std::max(1, static_cast<int>(std::ceil(area.w / cell_)))),
      rows_(std::max(1, static_cast<int>(std::ceil(area.h / cell_)))),
      words_per_row_((columns_ + 63) / 64) {
  if (!spare_bits.empty()) bits_ = std::move(spare_bits.back()), spare_bits.pop_back();
  bits_.assign(static_cast<size_t>(words_per_row_) * rows_, 0);
}

OccupancyGrid::~OccupancyGrid() {
  constexpr size_t kKept = 4;  // grids alive at once in one thread, at most
  if (spare_bits.size() < kKept) spare_bits.push_back(std::move(bits_));
}

void OccupancyGrid::mark(int row, int first, int last) {
  std::uint64_t* words = bits_.data() + static_cast<size_t>(row) * words_per_row_;
  for (int column = first; column <= last;) {
    const int word = column / 64, end = std::min(last + 1, (word + 1) * 64);
    words[word] |= bits_between(column % 64, end - word * 64);
    column = end;
  }
}

bool OccupancyGrid::any(int row, int first, int last) const {
  const std::uint64_t* words = bits_.data() + static_cast<size_t>(row) * words_per_row_;
  for (int column = first; column < last;) {
    const int word = column / 64, end = std::min(last, (word + 1) * 64);
    if (words[word] & bits_between(column % 64, end - word * 64)) return true;
    column = end;
  }
  return false;
}

#if defined(__x86_64__)
[[gnu::target_clones("popcnt", "default")]]  // the instruction, where the processor has it, not libgcc's loop
#endif
long long OccupancyGrid::count(int row, int first, int last) const {
  const std::uint64_t* words = bits_.data() + static_cast<size_t>(row) * words_per_row_;
  long long n = 0;
  for (int column = first; column < last;) {
    const int word = column / 64, end = std::min(last, (word + 1) * 64);
    n += std::popcount(words[word] & bits_between(column % 64, end - word * 64));
    column = end;
  }
  return n;
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
    if (c0 <= c1) mark(row, c0, c1);
  }
}

void OccupancyGrid::mark_polygon(const std::vector<Point>& polygon) {
  // Even-odd scanlines through the cells' centres; the edges are marked as
  // segments, so a cell the polygon only grazes is taken too. An edge (q, p)
  // crosses the line y when exactly one end is above it: y in [low, high) of
  // its ends. The edges are swept in order of their low ends, so a row looks
  // only at those crossing it (a road's outline has an edge a pixel column).
  struct Edge {
    double low, high;
    size_t p, q;  ///< polygon[i] and the point before it, as the crossing's formula takes them
  };
  std::vector<Edge> edges;
  for (size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
    const double a = polygon[i].y(), b = polygon[j].y();
    if (std::isfinite(a) && std::isfinite(b) && a != b) edges.push_back({std::min(a, b), std::max(a, b), i, j});
  }
  if (edges.empty()) return;
  std::sort(edges.begin(), edges.end(), [](const Edge& a, const Edge& b) { return a.low < b.low; });
  double top = 1e300, bottom = -1e300;
  for (const Point& p : polygon) top = std::min(top, p.y()), bottom = std::max(bottom, p.y());
  const int first = clamped_floor((top - area_.y) / cell_, 0, rows_);
  const int last = clamped_floor((bottom - area_.y) / cell_, -1, rows_ - 1);
  std::vector<size_t> active;  // indices into edges whose low end is at or above the row
  std::vector<double> xs;
  size_t next = 0;
  for (int row = first; row <= last; ++row) {
    const double y = area_.y + (row + 0.5) * cell_;
    for (; next < edges.size() && edges[next].low <= y; ++next) active.push_back(next);
    std::erase_if(active, [&](size_t e) { return edges[e].high <= y; });  // y below the edge: never again
    xs.clear();
    for (size_t e : active) {
      const Point &p = polygon[edges[e].p], &q = polygon[edges[e].q];
      xs.push_back(p.x() + (y - p.y()) * (q.x() - p.x()) / (q.y() - p.y()));
    }
    std::sort(xs.begin(), xs.end());
    for (size_t k = 0; k + 1 < xs.size(); k += 2) {
      const int c0 = clamped_floor((xs[k] - area_.x) / cell_, 0, columns_);
      const int c1 = clamped_floor((xs[k + 1] - area_.x) / cell_, -1, columns_ - 1);
      if (c0 <= c1) mark(row, c0, c1);
    }
  }
}

void OccupancyGrid::add(const OutlineShape& shape, bool edges) {
  // Skipped when out of every cell's reach (mark_segment's: the clearance and half a cell's diagonal).
  const PixelRect& b = shape.bounds;
  const double reach = clearance_ + 0.7072 * cell_;
  if (b.x > area_.x + area_.w + reach || b.x + b.w < area_.x - reach || b.y > area_.y + area_.h + reach ||
      b.y + b.h < area_.y - reach)
    return;
  if (edges)
    for (const auto& [a, c] : shape.segments) mark_segment(a, c, shape.half_width + clearance_);
  for (const auto& polygon : shape.polygons) mark_polygon(polygon);
}

namespace {
/// Whether `wider` marks every cell `shape`'s segments mark: the same path, at least as wide.
bool edges_covered_by(const OutlineShape& shape, const OutlineShape& wider) {
  return wider.half_width >= shape.half_width && wider.segments == shape.segments;
}
}  // namespace

void OccupancyGrid::add_shapes(const std::vector<OutlineShape>& shapes, size_t first) {
  for (size_t i = first; i < shapes.size(); ++i) {
    // Of two equally wide, the later one marks the path; no two leave it to each other.
    const bool covered = (i + 1 < shapes.size() && edges_covered_by(shapes[i], shapes[i + 1])) ||
                         (i > first && shapes[i - 1].half_width > shapes[i].half_width &&
                          edges_covered_by(shapes[i], shapes[i - 1]));
    add(shapes[i], !covered);
  }
}

void OccupancyGrid::add_box(const PixelRect& r) {
  const CellRange range = cells_of({r.x - clearance_, r.y - clearance_, r.w + 2 * clearance_, r.h + 2 * clearance_});
  if (range.c0 <= range.c1 && range.r0 <= range.r1) boxes_.push_back(range);
}

OccupancyGrid::CellRange OccupancyGrid::query_cells(const PixelRect& r) const {
  return {clamped_floor((r.x - area_.x) / cell_, 0, columns_), clamped_floor((r.x + r.w - area_.x) / cell_ + 1, 0, columns_),
          clamped_floor((r.y - area_.y) / cell_, 0, rows_), clamped_floor((r.y + r.h - area_.y) / cell_ + 1, 0, rows_)};
}

namespace {
/// Cells of a placed box inside a query's (exclusive ends c1, r1).
long long overlap_cells(int c0, int c1, int r0, int r1, int b_c0, int b_c1, int b_r0, int b_r1) {
  const long long across = std::min(c1 - 1, b_c1) - std::max(c0, b_c0) + 1;
  const long long down = std::min(r1 - 1, b_r1) - std::max(r0, b_r0) + 1;
  return across > 0 && down > 0 ? across * down : 0;
}
}  // namespace

long long OccupancyGrid::taken(const PixelRect& r) const {
  const auto [c0, c1, r0, r1] = query_cells(r);
  long long cells = 0;
  for (int row = r0; row < r1; ++row) cells += count(row, c0, c1);
  for (const CellRange& b : boxes_) cells += overlap_cells(c0, c1, r0, r1, b.c0, b.c1, b.r0, b.r1);
  return cells;
}

bool OccupancyGrid::free(const PixelRect& r) const {
  const auto [c0, c1, r0, r1] = query_cells(r);
  for (const CellRange& b : boxes_)
    if (overlap_cells(c0, c1, r0, r1, b.c0, b.c1, b.r0, b.r1) > 0) return false;
  for (int row = r0; row < r1; ++row)
    if (any(row, c0, c1)) return false;
  return true;
}

bool OccupancyGrid::same_cells(const OccupancyGrid& other) const {
  return area_.x == other.area_.x && area_.y == other.area_.y && area_.w == other.area_.w && area_.h == other.area_.h &&
         cell_ == other.cell_ && clearance_ == other.clearance_;
}

std::unique_ptr<OccupancyGrid> OccupancyGrid::empty_like() const {
  return std::make_unique<OccupancyGrid>(area_, cell_, clearance_);
}

void OccupancyGrid::copy_marks(const OccupancyGrid& other) {
  if (!same_cells(other) || !boxes_.empty()) throw std::logic_error("OccupancyGrid::copy_marks: another grid's cells");
  bits_ = other.bits_;
}

}  // namespace vibra::render
