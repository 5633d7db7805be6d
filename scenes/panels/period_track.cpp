// The period panel's curve: the last period completed by each time, from upward zero crossings.
#include "scenes/panels/period_track.hpp"

#include <algorithm>
#include <cmath>

namespace vibra::scenes {

PeriodTrack::PeriodTrack(int value_column, int velocity_column)
    : value_column_(value_column), velocity_column_(velocity_column) {}

double PeriodTrack::at(std::span<const double> row) {
  const double t = row[0];
  // A row where the run has no sample of its own (NaN, a comparison's
  // member between its samples) adds no crossing.
  if (t > newest_t_ && std::isfinite(row[value_column_]) && std::isfinite(row[velocity_column_])) {
    meter_.add(t, row[value_column_], row[velocity_column_]);
    newest_t_ = t;
  }
  const auto& c = meter_.crossings();
  const auto after = std::upper_bound(c.begin(), c.end(), t);  // the first crossing later than t
  if (after - c.begin() < 2) return NAN;
  return *(after - 1) - *(after - 2);
}

}  // namespace vibra::scenes
