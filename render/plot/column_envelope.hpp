// ColumnEnvelope: a whole curve decimated to one min/max cell per pixel column.
#pragma once
#include <algorithm>
#include <optional>
#include <utility>
#include <vector>

#include "render/draw/canvas.hpp"
#include "render/plot/envelope_cell.hpp"

namespace vibra::render {

/// A curve decimated to one EnvelopeCell per pixel column. Drawing it costs
/// the same whatever the number of samples, and no peak is lost.
class ColumnEnvelope {
 public:
  /// `columns` columns spanning x in [x0, x1].
  ColumnEnvelope(int columns, double x0, double x1);

  void add(double x, double y);
  void clear();
  int columns() const { return static_cast<int>(cells_.size()); }
  double x0() const { return x0_; }
  double x1() const { return x1_; }
  /// Column of x, clamped to the range.
  int column_of(double x) const;
  /// The last column before `column` that holds a value, or -1: where a curve
  /// drawn up to `column` in pieces must restart so that its pieces join
  /// across the empty columns between coarse samples.
  int used_before(int column) const;

  /// A column's two extremes in the order they occurred (the smallest first
  /// when it came no later than the largest); nullopt for an empty column.
  std::optional<std::pair<double, double>> extremes_in_order(int column) const;
  /// The same curve in columns / factor columns (rounded up): each new column
  /// merges `factor` neighbours, keeping their extremes and their order.
  ColumnEnvelope coarsened(int factor) const;

  /// Pixel polyline through columns [0, last_column], with to_pixel(x, y).
  template <class ToPixel>
  std::vector<Point> polyline(int last_column, ToPixel&& to_pixel) const {
    return polyline(0, last_column, std::forward<ToPixel>(to_pixel));
  }

  /// Pixel polyline through columns [first_column, last_column], with
  /// `to_pixel(x, y)` at the x where each kept sample happened.
  template <class ToPixel>
  std::vector<Point> polyline(int first_column, int last_column, ToPixel&& to_pixel) const {
    std::vector<Point> out;
    for (int c = std::max(0, first_column); c <= last_column && c < columns(); ++c)
      cells_[c].visit_in_order([&](double x, double y) { out.push_back(to_pixel(x, y)); });
    return out;
  }

 private:
  std::vector<EnvelopeCell> cells_;
  double x0_, x1_;
};

}  // namespace vibra::render
