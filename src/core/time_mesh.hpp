#pragma once
#include <string>
#include <vector>

#include "core/parameters.hpp"
#include "core/scheme.hpp"

namespace vibra {

/// The mesh t_n = n dt, n = 0..steps, and the scheme that walks it.
struct TimeMesh {
  Scheme scheme = Scheme::centered;
  double dt = 0;
  double T = 0;             ///< steps * dt; infinite for unbounded runs
  long long steps = 0;      ///< SolutionStream<D>::unbounded when T = inf
  double period = 0;        ///< small-oscillation period, 0 when the model has none
};

/// Defaults a model gives its time keys.
struct TimeDefaults {
  std::string scheme = "centered";
  std::string steps_per_period = "60";
  std::string periods = "10";
};

/// The time keys every model has: scheme, dt | steps_per_period, T | periods.
std::vector<KeySpec> time_keys(const TimeDefaults&);

/// Reads the time keys. `period` is the small-oscillation period (0: none, so
/// dt and T must be given); `fastest_w` the largest small-oscillation angular
/// frequency, for the stability limit. Throws UsageError for dt <= 0, T <= 0,
/// both dt and steps_per_period given, and dt above the scheme's limit.
TimeMesh resolve_time_mesh(const Parameters&, double period, double fastest_w);

}  // namespace vibra
