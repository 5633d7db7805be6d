// OccupancyGrid: a drawing's outline rasterized into cells, one bit each, to test whether a box is free.
#pragma once
#include <cstdint>
#include <memory>
#include <vector>

#include "render/labels/outline.hpp"

namespace vibra::render {

/// An outline rasterized into cells of a few pixels, conservatively (a cell
/// any shape comes within `clearance` of is taken), a bit a cell: whether a
/// box is free is a population count of a few words per row of the box (the
/// label placer tries hundreds of spots a frame), and a grid costs no table
/// to build (a summed-area table of a 720p grid was a tenth of a frame).
class OccupancyGrid {
 public:
  /// Covers `area`; cells of `cell` pixels.
  OccupancyGrid(const PixelRect& area, double cell, double clearance);
  ~OccupancyGrid();
  OccupancyGrid(const OccupancyGrid&) = delete;
  OccupancyGrid& operator=(const OccupancyGrid&) = delete;

  /// Marks the shape: its segments' reach and its polygons' insides. Without
  /// `edges`, the polygons alone (another shape marks the same segments at
  /// least as wide: a fill's outline stroked, an arrow on its casing).
  void add(const OutlineShape&, bool edges = true);
  /// Marks shapes[first ..]: the same cells as add() of each, but a path two
  /// neighbours share (a fill and the stroke of its outline, an arrow's
  /// shaft on its casing) is marked once, at the larger width.
  void add_shapes(const std::vector<OutlineShape>& shapes, size_t first = 0);
  /// An empty grid with this one's area, cells and clearance.
  std::unique_ptr<OccupancyGrid> empty_like() const;
  /// Whether both grids cover the same area with the same cells and clearance.
  bool same_cells(const OccupancyGrid&) const;
  /// Takes `other`'s marked cells as this grid's (same_cells, no boxes yet):
  /// a copy of its bits instead of marking its shapes again.
  void copy_marks(const OccupancyGrid& other);
  /// A placed label: the cells it covers, with the clearance, count as
  /// taken. Kept beside the table, so placing a label does not rebuild it.
  void add_box(const PixelRect&);
  /// How many taken cells the box touches (0: free).
  long long taken(const PixelRect&) const;
  /// Whether the box touches no taken cell: taken(box) == 0, stopping at the first taken cell.
  bool free(const PixelRect&) const;

 private:
  struct CellRange {
    int c0, c1, r0, r1;  ///< inclusive
  };
  /// The cells a pixel box touches, clamped to the grid (empty: c0 > c1 or r0 > r1).
  CellRange cells_of(const PixelRect&) const;
  void mark_segment(const Point& a, const Point& b, double reach);
  void mark_polygon(const std::vector<Point>& polygon);
  /// Marks cells [first, last] of `row` taken.
  void mark(int row, int first, int last);
  /// Taken cells among [first, last) of `row`.
  long long count(int row, int first, int last) const;
  /// Whether any cell among [first, last) of `row` is taken.
  bool any(int row, int first, int last) const;
  /// The cells a query box touches: columns c0 .. c1 - 1, rows r0 .. r1 - 1 (exclusive ends, unlike CellRange).
  CellRange query_cells(const PixelRect&) const;

  /// A frame places labels in several grids of the same size one after
  /// another: the storage is handed on from grid to grid within a thread,
  /// not allocated (and faulted in page by page) for each.
  std::vector<std::uint64_t> bits_;  ///< row by row, words_per_row_ words each, bit c % 64 of word c / 64

  PixelRect area_;
  double cell_, clearance_;
  int columns_, rows_, words_per_row_;
  std::vector<CellRange> boxes_;  ///< placed labels' cells
};

}  // namespace vibra::render
