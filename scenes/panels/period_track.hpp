// The period panel's curve: the last period completed by each time, from upward zero crossings.
#pragma once
#include <span>

#include "core/analysis/frequency/period_meter.hpp"

namespace vibra::scenes {

/// The periods of one run's main quantity as a curve of the `period` panel:
/// at time t, the last period completed by t (time between the two latest
/// upward zero crossings, located inside the step as `vibra analyze period`
/// does), NaN before the second crossing. Fed rows in time order (the
/// pre-pass); a row not later than the newest one fed (a later pass over
/// the same run, a frame between steps) is answered from the crossings
/// found, so it may be asked again in any order. One per run: a comparison
/// makes one per member.
class PeriodTrack {
 public:
  /// Columns of the main quantity and of its velocity in a row.
  PeriodTrack(int value_column, int velocity_column);

  double at(std::span<const double> row);

 private:
  int value_column_, velocity_column_;
  PeriodMeter meter_;
  double newest_t_ = -1e300;
};

}  // namespace vibra::scenes
