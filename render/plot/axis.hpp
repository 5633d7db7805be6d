// Axis: a range and its tick labels, linear or logarithmic.
#pragma once
#include <string>
#include <vector>

namespace vibra::render {

enum class AxisScale { linear, logarithmic };

/// A tick: its value and label (Pango markup; "" marks a grid line without a label).
struct AxisTick {
  double value;
  std::string label;
};

/// Labels of linear ticks `step` apart. Everyday magnitudes get plain
/// decimals and an empty `common`. Tiny or huge numbers, or ticks that differ
/// only far below their size (r = 1 ± 10^-9), get short labels sharing a
/// power of ten and, in the latter case, an offset, both stated once in
/// `common` for the axis's label, as matplotlib does: tick 2 with common
/// "×10^-9 + 1" reads 1 + 2×10^-9.
struct LinearTickLabels {
  std::vector<std::string> labels;  ///< one per tick, Pango markup
  std::string common;               ///< "", "×10<sup>−9</sup>", "+ 1", or both
  bool scaled = false;              ///< the labels are in units of a power of ten
};
LinearTickLabels linear_tick_labels(const std::vector<double>& values, double step);

/// One axis of a figure panel: the range it shows and where a value sits
/// along it, linearly or by decades. Knows nothing of pixels.
class Axis {
 public:
  explicit Axis(AxisScale scale = AxisScale::linear) : scale_(scale) {}
  AxisScale scale() const { return scale_; }

  /// Whether v can be placed: finite, and > 0 on a logarithmic axis.
  bool shows(double v) const;
  /// Shows exactly [lo, hi] (for a shared time axis: no margin).
  void set_range(double lo, double hi);
  /// Shows data in [lo, hi] with a 5% margin, so extremes do not touch the
  /// frame; an empty or one-value range is widened.
  void fit(double lo, double hi);
  /// Widens the range about its middle by `factor` >= 1 (for equal aspect).
  void widen(double factor);
  /// The range's lower and upper end, as values.
  double lo() const;
  double hi() const;

  /// 0 at lo(), 1 at hi() (in decades on a logarithmic axis).
  double fraction(double v) const;

  /// About `target` labelled ticks inside the range, and on a logarithmic axis
  /// unlabelled minor ticks (2..9 times a power of ten) for the grid; or the
  /// ticks set by place_ticks_at().
  std::vector<AxisTick> ticks(int target) const;
  /// Ticks at exactly these values (e.g. the dt values of a study), labelled
  /// with 4 significant digits.
  void place_ticks_at(std::vector<double> values) { fixed_ticks_ = std::move(values); }

 private:
  double to_axis(double v) const;
  AxisScale scale_;
  double lo_ = 0, hi_ = 1;  ///< in axis units: the value, or log10 of it
  std::vector<double> fixed_ticks_;
};

}  // namespace vibra::render
