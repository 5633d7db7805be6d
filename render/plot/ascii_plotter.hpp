// The classic line-by-line ASCII plotter: time runs down the page, one line per time step.
#pragma once
#include <span>
#include <string>
#include <string_view>

namespace vibra::render {

struct AsciiPlotterOptions {
  double ymin, ymax;
  int width = 68;
  std::string symbols = "*o+x@";
};

/// The classic line-by-line ASCII plotter (scitools avplotter.Plotter): time
/// runs down the page, y across it, one line per time step.
///
/// A line is width + 1 characters, columns 0..width, then the out-of-range
/// values. Value y[i] is drawn with symbols[i % symbols.size()] at column
/// std::round((y - ymin) / (ymax - ymin) * width), computed in exactly that
/// order (halves round away from zero, as Python 2's round did). The range is
/// closed: ymin lands in column 0, ymax in column width. Series are drawn in
/// order, so a later one overwrites an earlier one in the same column. When
/// ymin < 0 < ymax, a '|' marks y = 0 at the column 0 maps to, drawn last,
/// over any symbol there.
///
/// A value outside [ymin, ymax], or not finite, is not drawn; instead each
/// such value, in series order, is appended as printf(" %.1E"): one space,
/// then e.g. "1.5E+00", "-2.0E-03", "INF", "-INF", or "NAN" (NaN's sign is
/// dropped, as Python does). There is no trailing space or counter.
class AsciiPlotter {
 public:
  /// Throws std::invalid_argument for non-finite bounds, ymin >= ymax, a range
  /// whose width overflows, width < 1, or no symbols.
  explicit AsciiPlotter(AsciiPlotterOptions);

  /// The line for values y[0], y[1], ...; valid until the next call. It lives
  /// in a buffer that is reused, so lines allocate nothing after the first
  /// (or the first with more values than before).
  std::string_view line(std::span<const double> values);

 private:
  int column(double y) const;

  AsciiPlotterOptions options_;
  int axis_column_ = -1;  // -1: zero is not strictly inside the range
  std::string line_;
};

}  // namespace vibra::render
