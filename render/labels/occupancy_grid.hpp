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

  void add(const OutlineShape&);
  void add_box(const PixelRect&);
  /// How many taken cells the box touches (0: free). Call after adding.
  long long taken(const PixelRect&);

 private:
  void mark_segment(const Point& a, const Point& b, double reach);
  void mark_polygon(const std::vector<Point>& polygon);
  void mark(int column, int row) { cells_[static_cast<size_t>(row) * columns_ + column] = 1; }
  void build_sums();

  PixelRect area_;
  double cell_, clearance_;
  int columns_, rows_;
  std::vector<unsigned char> cells_;
  std::vector<long long> sums_;  ///< (rows + 1) x (columns + 1)
  bool sums_current_ = false;
};

}  // namespace vibra::render
