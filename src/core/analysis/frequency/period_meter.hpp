// PeriodMeter: upward zero crossings and maxima located between mesh points, one sample at a time.
#pragma once
#include <vector>

#include "core/trajectory.hpp"

namespace vibra {

/// Finds an oscillation's upward zero crossings and its maxima between mesh
/// points, fed one sample (t, u, u') at a time. Inside each step u is the cubic
/// Hermite polynomial through u and u' at both ends (4th order, so the timing
/// is as accurate as the best schemes): a crossing is its root, a maximum is
/// where its derivative vanishes.
class PeriodMeter {
 public:
  void add(double t, double u, double v);

  /// Times of the upward zero crossings (u < 0 before, u >= 0 after), in order.
  const std::vector<double>& crossings() const { return crossings_; }
  /// peaks()[i]: the largest maximum of u between crossings i and i+1; the
  /// last entry may be that after the last crossing (when the run reached one).
  /// NaN where a window held no maximum.
  std::vector<double> peaks() const;

 private:
  void close_window();

  bool started_ = false;
  double t_ = 0, u_ = 0, v_ = 0;  ///< the previous sample
  std::vector<double> crossings_;
  std::vector<double> peaks_;        ///< of the closed windows
  double window_peak_ = -INFINITY;  ///< largest maximum since the last crossing
};

/// One period of `vibra analyze period`.
struct MeasuredPeriod {
  int i;                ///< 0, 1, ...
  double t;             ///< the upward crossing that ends the period
  double period;        ///< time since the previous upward crossing
  double log_decrement; ///< ln(a_i / a_{i+1}) of the maxima in this period and the next; NaN if unknown
};

/// Every period of the trajectory's main quantity (column 1, its velocity
/// from velocity_column). Streams the run; memory grows with the periods.
std::vector<MeasuredPeriod> measure_periods(Trajectory&);

}  // namespace vibra
