// PlotPanel: a moving time plot with axes, ticks and curves drawn through their pixel-column envelopes.
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "render/draw/canvas.hpp"
#include "render/draw/elements/shapes.hpp"
#include "render/plot/column_envelope.hpp"

namespace vibra::render {

/// Tick positions at 1-2-5 steps covering [lo, hi], about `target` of them.
std::vector<double> nice_ticks(double lo, double hi, int target);
/// A tick label: short, without trailing zeros, with a real minus sign.
std::string tick_label(double value, double step);

/// One plot panel: a frame, grid, ticks with labels, a y label, and curves
/// against a horizontal axis (time). Knows nothing of what it plots.
class PlotPanel {
 public:
  /// `outer` is the panel's whole rectangle, labels included.
  PlotPanel(const PixelRect& outer, double scale);

  void set_x_range(double x0, double x1);
  /// The y range is widened by kYMargin of its span on each side (and made non-empty).
  void set_y_range(double y0, double y1);
  static constexpr double kYMargin = 0.05;
  double x0() const { return x0_; }
  double x1() const { return x1_; }
  const PixelRect& area() const { return area_; }
  /// The frame's size against 720p (Canvas::scale()).
  double scale() const { return scale_; }
  Point to_pixel(double x, double y) const;
  /// Columns of the plot area, for a ColumnEnvelope.
  int columns() const { return static_cast<int>(area_.w); }

  /// Frame, grid, ticks and labels. `x_label` empty: no x tick labels (stacked panels).
  void draw_axes(Canvas&, const std::string& y_label_markup, const std::string& x_label_markup) const;
  /// A curve from an envelope over this panel's x range, up to `up_to_x`.
  void draw_envelope(Canvas&, const ColumnEnvelope&, double up_to_x, const Stroke&) const;
  /// The envelope's columns [first_column, last_column] only (to extend a curve drawn before).
  void draw_envelope_columns(Canvas&, const ColumnEnvelope&, int first_column, int last_column, const Stroke&) const;
  /// A known function y = f(x) over [from_x, to_x], evaluated at every half
  /// pixel column: smooth at the panel's resolution, whatever the mesh.
  void draw_function(Canvas&, const std::function<double(double)>& f, double from_x, double to_x, const Stroke&) const;
  /// A vertical cursor line at x with a dot at (x, y).
  void draw_cursor(Canvas&, double x, double y, const Color&) const;
  /// A legend entry: its markup, and its line as the curve is drawn.
  struct LegendItem {
    std::string label;
    Color color;
    bool dashed = false;
  };
  /// Legend entries on the title row, right of the y label `y_label_markup`
  /// (as given to draw_axes), where they cover no data; where the row is too
  /// narrow, under the plot when `margin_below_free` (draw_axes drew no x
  /// tick labels there), else in the plot's top-right corner.
  void draw_legend(Canvas&, const std::vector<LegendItem>& entries, const std::string& y_label_markup,
                   bool margin_below_free = false) const;

 private:
  /// The y label as drawn: with the ticks' common factor, if any.
  std::string y_title(const std::string& y_label_markup, int y_target) const;
  /// Labelled ticks to aim for on the y (`vertical`) or x axis, so that their labels keep apart.
  int tick_target(Canvas&, bool vertical) const;

  PixelRect outer_, area_;
  double scale_;
  double x0_ = 0, x1_ = 1, y0_ = -1, y1_ = 1;
};

}  // namespace vibra::render
