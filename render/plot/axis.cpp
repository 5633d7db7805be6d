// Axis: a range and its tick labels, linear or logarithmic.
#include "render/plot/axis.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "render/plot/plot_panel.hpp"

namespace vibra::render {

namespace {
const std::string kMinus = "\u2212";

std::string power_of_ten(int exponent) {
  return "10<sup>" + (exponent < 0 ? kMinus + std::to_string(-exponent) : std::to_string(exponent)) + "</sup>";
}

/// Linear tick labels for a figure: one power of ten written on every label
/// (a figure's axes never need an offset: Axis::fit keeps their relative span
/// at least 1e-5).
std::vector<AxisTick> label_linear(const std::vector<double>& values) {
  std::vector<AxisTick> out;
  if (values.empty()) return out;
  const double step = values.size() > 1 ? values[1] - values[0] : std::max(std::abs(values[0]), 1.0);
  const LinearTickLabels labels = linear_tick_labels(values, step);
  for (size_t i = 0; i < values.size(); ++i) {
    std::string label = labels.labels[i];
    if (!labels.common.empty() && std::abs(values[i]) > 1e-9 * step) label += labels.common;
    out.push_back({values[i], label});
  }
  return out;
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

LinearTickLabels linear_tick_labels(const std::vector<double>& values, double step) {
  LinearTickLabels out;
  if (values.empty()) return out;
  double largest = 0;
  for (double v : values) largest = std::max(largest, std::abs(v));
  const double span = std::max(values.back() - values.front(), step);
  // Ticks that differ in their fifth significant digit or beyond: subtract a
  // round number near them, so the labels show only what differs.
  double offset = 0;
  if (span < 1e-4 * largest) {
    const double round_to = std::pow(10.0, std::floor(std::log10(span)) + 1);
    offset = std::round(values.front() / round_to) * round_to;
  }
  double rest = 0;
  for (double v : values) rest = std::max(rest, std::abs(v - offset));
  out.scaled = rest >= 1e5 || (rest > 0 && rest < 1e-3);
  const int exponent = out.scaled ? static_cast<int>(std::floor(std::log10(rest))) : 0;
  const double unit = std::pow(10.0, exponent);
  for (double v : values) out.labels.push_back(tick_label((v - offset) / unit, step / unit));
  if (out.scaled) out.common = "×" + power_of_ten(exponent);
  if (offset != 0) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.12g", std::abs(offset));
    out.common += std::string(out.common.empty() ? "" : " ") + (offset < 0 ? kMinus : "+") + " " + buf;
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
