// RollingEnvelope: the latest stretch of a curve in one min/max cell per pixel column, in a ring of bounded size.
#pragma once
#include <algorithm>
#include <vector>

#include "render/draw/canvas.hpp"
#include "render/plot/envelope_cell.hpp"

namespace vibra::render {

/// The most recent stretch of a curve, decimated to one EnvelopeCell per
/// pixel column, in a ring: memory is proportional to the columns kept,
/// never to the length of the run or to how many samples fall in a column.
class RollingEnvelope {
 public:
  /// Cells of width `column_width` in x; keeps the newest `capacity` columns.
  RollingEnvelope(double column_width, int capacity);

  void add(double x, double y);
  double column_width() const { return width_; }
  /// Absolute column index of x (floor(x / column_width)).
  long long column_of(double x) const;

  /// Polyline through the kept columns in [first, last] (absolute indices),
  /// with to_pixel(x, y) at the x where each kept sample happened.
  template <class ToPixel>
  std::vector<Point> polyline(long long first, long long last, ToPixel&& to_pixel) const {
    std::vector<Point> out;
    first = std::max(first, newest_ - static_cast<long long>(cells_.size()) + 1);
    for (long long c = first; c <= last && c <= newest_; ++c) {
      const Column& k = cells_[slot(c)];
      if (k.column == c) k.cell.visit_in_order([&](double x, double y) { out.push_back(to_pixel(x, y)); });
    }
    return out;
  }

 private:
  struct Column {
    long long column = -1;  ///< absolute column held, -1 = empty
    EnvelopeCell cell;
  };
  size_t slot(long long column) const { return static_cast<size_t>(column % static_cast<long long>(cells_.size())); }

  double width_;
  std::vector<Column> cells_;
  long long newest_ = -1;
};

}  // namespace vibra::render
