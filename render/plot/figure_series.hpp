// A figure's series (points, curve or path, decimated as they stream) and how each is drawn.
#pragma once
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "render/draw/color.hpp"
#include "render/draw/polyline/decimated_path.hpp"
#include "render/plot/column_envelope.hpp"

namespace vibra::render {

/// How a series is drawn. Widths and sizes are in 720p pixels.
struct SeriesStyle {
  Color color = palette::blue;
  double line_width = 2.4;  ///< 0: markers only
  bool dashed = false;
  bool markers = false;     ///< a filled circle at every point
};

/// One curve of a figure panel and its data, fed a point at a time.
/// - points: kept as given (a table's few rows; markers need every point);
/// - curve: y as a function of x over a range known in advance (a time
///   series): once it holds more points than `columns`, it is decimated to a
///   ColumnEnvelope, so a run of 1e7 steps costs `columns` cells;
/// - path: (x(s), y(s)), thinned by a DecimatedPath.
class Series {
 public:
  enum class Kind { points, curve, path };

  Series(Kind kind, std::string label, SeriesStyle style, int columns = 0, double x0 = 0, double x1 = 1);

  void add(double x, double y);

  Kind kind() const { return kind_; }
  const std::string& label() const { return label_; }
  /// A label learnt after the data (e.g. "blew up at t = 3.1").
  void set_label(std::string label) { label_ = std::move(label); }
  const SeriesStyle& style() const { return style_; }
  /// The data as polylines in data coordinates (a path or a point set may be several).
  std::vector<std::vector<Point>> polylines() const;
  /// Calls `visit(x, y)` for every point that polylines() holds, without copying.
  void for_each_point(const std::function<void(double, double)>& visit) const;
  bool empty() const { return count_ == 0; }

 private:
  Kind kind_;
  std::string label_;
  SeriesStyle style_;
  int columns_;
  double x0_, x1_;
  long long count_ = 0;
  std::vector<Point> points_;
  std::optional<ColumnEnvelope> envelope_;
  std::optional<DecimatedPath> path_;
};

}  // namespace vibra::render
