// OccupancyGrid: a drawing's outline rasterized into cells with a summed-area table, to test whether a box is free.
#pragma once
#include <vector>

#include "render/labels/outline.hpp"

namespace vibra::render {

/// An outline rasterized into cells of a few pixels, conservatively (a cell
/// any shape comes within `clearance` of is taken), with a summed-area table,
/// so that whether a box is free costs four lookups: the label placer tries
/// hundreds of spots a frame.
class OccupancyGrid {
 public:
  /// Covers `area`; cells of `cell` pixels.
  OccupancyGrid(const PixelRect& area, double cell, double clearance);
  ~OccupancyGrid();
  OccupancyGrid(const OccupancyGrid&) = delete;
  OccupancyGrid& operator=(const OccupancyGrid&) = delete;

  void add(const OutlineShape&);
  /// A placed label: the cells it covers, with the clearance, count as
  /// taken. Kept beside the table, so placing a label does not rebuild it.
  void add_box(const PixelRect&);
  /// How many taken cells the box touches (0: free). Call after adding.
  long long taken(const PixelRect&);

 private:
  struct CellRange {
    int c0, c1, r0, r1;  ///< inclusive
  };
  /// The cells a pixel box touches, clamped to the grid (empty: c0 > c1 or r0 > r1).
  CellRange cells_of(const PixelRect&) const;
  void mark_segment(const Point& a, const Point& b, double reach);
  void mark_polygon(const std::vector<Point>& polygon);
  void mark(int column, int row) { buffers_.cells[static_cast<size_t>(row) * columns_ + column] = 1; }
  void build_sums();

  /// The cells and their summed-area table. A frame places labels in
  /// several grids of the same size one after another: the storage is
  /// handed on from grid to grid within a thread, not allocated (and
  /// faulted in page by page) for each.
  struct Buffers {
    std::vector<unsigned char> cells;
    std::vector<int> sums;  ///< (rows + 1) x (columns + 1)
  };

  PixelRect area_;
  double cell_, clearance_;
  int columns_, rows_;
  Buffers buffers_;
  std::vector<CellRange> boxes_;  ///< placed labels' cells
  bool sums_current_ = false;
};

}  // namespace vibra::render
