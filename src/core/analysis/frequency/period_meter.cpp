// PeriodMeter: upward zero crossings and maxima located between mesh points, one sample at a time.
#include "core/analysis/frequency/period_meter.hpp"

#include <algorithm>
#include <cmath>
#include <functional>

namespace vibra {

namespace {
/// u on a step of length h as the cubic Hermite polynomial in s = (t - t_a)/h.
struct HermiteStep {
  double ua, ub, da, db;  ///< end values and end slopes d/ds = h u'

  double value(double s) const {
    const double s2 = s * s, s3 = s2 * s;
    return (2 * s3 - 3 * s2 + 1) * ua + (s3 - 2 * s2 + s) * da + (-2 * s3 + 3 * s2) * ub + (s3 - s2) * db;
  }
  double slope(double s) const {
    const double s2 = s * s;
    return (6 * s2 - 6 * s) * ua + (3 * s2 - 4 * s + 1) * da + (-6 * s2 + 6 * s) * ub + (3 * s2 - 2 * s) * db;
  }
};

/// A root of f in [0, 1] where f(0) < 0 <= f(1) (or the reverse with
/// `rising` false), by bisection to the last bit: called once per period.
double bisect(const std::function<double(double)>& f, bool rising) {
  double lo = 0, hi = 1;
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (lo + hi);
    ((f(mid) < 0) == rising ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}
}  // namespace

void PeriodMeter::add(double t, double u, double v) {
  if (!started_) {
    started_ = true, t_ = t, u_ = u, v_ = v;
    return;
  }
  const double h = t - t_;
  const HermiteStep step{u_, u, h * v_, h * v};
  // Both events can fall in one coarse step; handle them in time order.
  const double crossing = u_ < 0 && u >= 0 ? bisect([&](double s) { return step.value(s); }, true) : NAN;
  const double maximum = v_ > 0 && v <= 0 ? bisect([&](double s) { return step.slope(s); }, false) : NAN;
  const auto record_maximum = [&] { window_peak_ = std::max(window_peak_, step.value(maximum)); };
  if (!std::isnan(maximum) && !(maximum > crossing)) record_maximum();
  if (!std::isnan(crossing)) {
    close_window();
    crossings_.push_back(t_ + crossing * h);
  }
  if (!std::isnan(maximum) && maximum > crossing) record_maximum();
  t_ = t, u_ = u, v_ = v;
}

void PeriodMeter::close_window() {
  if (!crossings_.empty()) peaks_.push_back(std::isfinite(window_peak_) ? window_peak_ : NAN);
  window_peak_ = -INFINITY;
}

std::vector<double> PeriodMeter::peaks() const {
  std::vector<double> out = peaks_;
  if (!crossings_.empty() && std::isfinite(window_peak_)) out.push_back(window_peak_);
  return out;
}

std::vector<MeasuredPeriod> measure_periods(Trajectory& trajectory) {
  const int velocity = velocity_column(trajectory.info());
  PeriodMeter meter;
  std::vector<double> row(trajectory.width());
  do {
    trajectory.row(row);
    meter.add(row[0], row[1], row[velocity]);
  } while (trajectory.advance());
  const std::vector<double>& crossings = meter.crossings();
  const std::vector<double> peaks = meter.peaks();
  std::vector<MeasuredPeriod> periods;
  for (size_t i = 0; i + 1 < crossings.size(); ++i) {
    const bool known = i + 1 < peaks.size() && peaks[i] > 0 && peaks[i + 1] > 0;
    periods.push_back({static_cast<int>(i), crossings[i + 1], crossings[i + 1] - crossings[i],
                       known ? std::log(peaks[i] / peaks[i + 1]) : NAN});
  }
  return periods;
}

}  // namespace vibra
