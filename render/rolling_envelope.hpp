#pragma once
#include <vector>

#include "render/canvas.hpp"

namespace vibra::render {

/// The most recent stretch of a curve, decimated to one cell per pixel
/// column (first, last, min, max of the values in it), in a ring: memory is
/// proportional to the columns kept, never to the length of the run or to
/// how many samples fall in a column.
class RollingEnvelope {
 public:
  /// Cells of width `column_width` in x; keeps the newest `capacity` columns.
  RollingEnvelope(double column_width, int capacity);

  void add(double x, double y);
  double column_width() const { return width_; }
  /// Absolute column index of x (floor(x / column_width)).
  long long column_of(double x) const;

  /// Polyline through the kept columns in [first, last] (absolute indices),
  /// with to_pixel(x_of_column_centre, y).
  template <class ToPixel>
  std::vector<Point> polyline(long long first, long long last, ToPixel&& to_pixel) const {
    std::vector<Point> out;
    first = std::max(first, newest_ - static_cast<long long>(cells_.size()) + 1);
    for (long long c = first; c <= last && c <= newest_; ++c) {
      const Cell& k = cells_[slot(c)];
      if (k.column != c) continue;
      const double x = (c + 0.5) * width_;
      out.push_back(to_pixel(x, k.first));
      if (k.min == k.max) continue;  // one point for a flat column
      const bool rising = k.first <= k.last;
      out.push_back(to_pixel(x, rising ? k.min : k.max));
      out.push_back(to_pixel(x, rising ? k.max : k.min));
      out.push_back(to_pixel(x, k.last));
    }
    return out;
  }

 private:
  struct Cell {
    long long column = -1;  ///< absolute column held, -1 = empty
    double first = 0, last = 0, min = 0, max = 0;
  };
  size_t slot(long long column) const { return static_cast<size_t>(column % static_cast<long long>(cells_.size())); }

  double width_;
  std::vector<Cell> cells_;
  long long newest_ = -1;
};

}  // namespace vibra::render
