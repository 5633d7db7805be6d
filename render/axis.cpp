#include "render/axis.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "render/plot_panel.hpp"

namespace vibra::render {

namespace {
const std::string kMinus = "\u2212";

std::string power_of_ten(int exponent) {
  return "10<sup>" + (exponent < 0 ? kMinus + std::to_string(-exponent) : std::to_string(exponent)) + "</sup>";
}

/// m x 10^k as a plain decimal when every label is of everyday size, else in powers of ten.
std::string log_label(int m, int k, bool plain) {
  if (plain) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.*f", std::max(0, -k), m * std::pow(10.0, k));
    return buf;
  }
  return m == 1 ? power_of_ten(k) : std::to_string(m) + "×" + power_of_ten(k);
}
}  // namespace

std::vector<AxisTick> label_linear(const std::vector<double>& values) {
  std::vector<AxisTick> out;
  if (values.empty()) return out;
  const double step = values.size() > 1 ? values[1] - values[0] : std::max(std::abs(values[0]), 1.0);
  double largest = 0;
  for (double v : values) largest = std::max(largest, std::abs(v));
  const bool scientific = largest >= 1e5 || (largest > 0 && largest < 1e-3);
  const int exponent = scientific ? static_cast<int>(std::floor(std::log10(largest))) : 0;
  const double unit = std::pow(10.0, exponent);
  for (double v : values) {
    std::string label = tick_label(v / unit, step / unit);
    if (scientific && std::abs(v) > 1e-9 * step) label += "×" + power_of_ten(exponent);
    out.push_back({v, label});
  }
  return out;
}

bool Axis::shows(double v) const { return std::isfinite(v) && (scale_ == AxisScale::linear || v > 0); }

double Axis::to_axis(double v) const { return scale_ == AxisScale::linear ? v : std::log10(v); }

double Axis::lo() const { return scale_ == AxisScale::linear ? lo_ : std::pow(10.0, lo_); }
double Axis::hi() const { return scale_ == AxisScale::linear ? hi_ : std::pow(10.0, hi_); }

void Axis::set_range(double lo, double hi) {
  if (!shows(lo) || !shows(hi) || !(hi > lo)) return fit(lo, hi);
  lo_ = to_axis(lo), hi_ = to_axis(hi);
}

void Axis::fit(double lo, double hi) {
  if (!shows(lo) || !shows(hi) || hi < lo) lo = hi = scale_ == AxisScale::linear ? 0 : 1;
  double a = to_axis(lo), b = to_axis(hi);
  // Keep at least a 1e-5 relative span: the tick labels then need at most six decimals.
  const double least = scale_ == AxisScale::linear ? std::max(1e-5 * std::max(std::abs(a), std::abs(b)), 1e-300) : 0.1;
  if (b - a < least) {
    const double pad = scale_ == AxisScale::linear ? std::max(0.1 * std::abs(a), a == 0 ? 1.0 : least) : 0.5;
    a -= pad, b += pad;
  }
  const double margin = 0.05 * (b - a);
  lo_ = a - margin, hi_ = b + margin;
}

void Axis::widen(double factor) {
  const double middle = 0.5 * (lo_ + hi_), half = 0.5 * (hi_ - lo_) * std::max(1.0, factor);
  lo_ = middle - half, hi_ = middle + half;
}

double Axis::fraction(double v) const { return (to_axis(v) - lo_) / (hi_ - lo_); }

std::vector<AxisTick> Axis::ticks(int target) const {
  if (!fixed_ticks_.empty()) {
    std::vector<AxisTick> out;
    for (double v : fixed_ticks_) {
      if (!shows(v) || fraction(v) < -1e-9 || fraction(v) > 1 + 1e-9) continue;
      char buf[32];
      std::snprintf(buf, sizeof buf, "%.4g", std::abs(v));
      out.push_back({v, (v < 0 ? kMinus : "") + buf});
    }
    return out;
  }
  if (scale_ == AxisScale::linear) return label_linear(nice_ticks(lo_, hi_, target));

  const double span = hi_ - lo_;
  const int first = static_cast<int>(std::ceil(lo_ - 1e-9)), last = static_cast<int>(std::floor(hi_ + 1e-9));
  const int every = std::max(1, static_cast<int>(std::ceil(span / std::max(1, target))));
  // With at most one power of ten in view, 2x and 5x get labels too, so the axis is readable.
  const bool label_minor = last - first < 1;
  const bool minor_grid = every == 1 && span <= 3;
  struct Mark {
    int m, k;
    bool labelled;
  };
  std::vector<Mark> marks;
  for (int k = first - 1; k <= last; ++k)
    for (int m = 1; m <= 9; ++m) {
      const double at = std::log10(m * std::pow(10.0, k));
      if (at < lo_ - 1e-9 || at > hi_ + 1e-9) continue;
      const bool major = m == 1 && (k - first) % every == 0;
      const bool labelled = major || (label_minor && (m == 2 || m == 5));
      if (labelled || minor_grid || m == 1) marks.push_back({m, k, labelled});
    }
  // Plain decimals read best from 0.001 to 1000; beyond, powers of ten.
  bool plain = true;
  for (const Mark& mark : marks)
    if (mark.labelled && (mark.k < -3 || mark.k > 3)) plain = false;
  std::vector<AxisTick> out;
  for (const Mark& mark : marks)
    out.push_back({mark.m * std::pow(10.0, mark.k), mark.labelled ? log_label(mark.m, mark.k, plain) : ""});
  return out;
}

}  // namespace vibra::render
