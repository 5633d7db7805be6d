// TimeMesh: t_n = n dt up to T and the scheme that walks it, with the adaptive tolerances checked.
#pragma once
#include <string>
#include <vector>

#include "core/input/parameters.hpp"
#include "core/scheme.hpp"

namespace vibra {

/// The mesh t_n = n dt, n = 0..steps, and the scheme that walks it. An
/// adaptive scheme (scheme_info(scheme).adaptive) takes steps of its own
/// between 0 and T instead: `steps` is then only the mesh's count, the size
/// of a frame-per-step render or a page's grid, and the run ends at T.
struct TimeMesh {
  Scheme scheme = Scheme::centered;
  double dt = 0;
  double T = 0;             ///< steps * dt; infinite for unbounded runs
  long long steps = 0;      ///< SolutionStream<D>::unbounded when T = inf
  double period = 0;        ///< small-oscillation period, 0 when the model has none
  double rtol = 1e-6;       ///< an adaptive scheme's tolerances (keys rtol, atol)
  double atol = 1e-9;

  bool adaptive() const { return scheme_info(scheme).adaptive; }
  /// What an adaptive stepper is asked for (its steps end at T, or on the
  /// mesh points with `on_mesh`).
  StepControl control(bool on_mesh = false) const { return {rtol, atol, T, on_mesh}; }
};

/// Defaults a model gives its time keys.
struct TimeDefaults {
  std::string scheme = "centered";
  std::string steps_per_period = "60";
  std::string periods = "10";
};

/// The time keys every model has: scheme, dt | steps_per_period, T | periods,
/// and the adaptive schemes' rtol and atol.
std::vector<KeySpec> time_keys(const TimeDefaults&);

/// `--allow-unstable`: from now on a dt above the scheme's stability limit is
/// run, with a warning on stderr, instead of refused (Fig 1.5 draws such a run).
/// A process that runs several command lines (the command-line fuzz target)
/// clears it with `false` before each.
void allow_unstable_steps(bool allowed = true);

/// Throws UsageError when the mesh's scheme is adaptive: `analysis` (e.g.
/// "analyze convergence, which halves dt,") needs the even mesh t_n = n dt.
void require_even_steps(const TimeMesh&, const std::string& analysis);

/// Reads the time keys. `period` is the small-oscillation period (0: none, so
/// dt and T must be given); `fastest_w` the largest small-oscillation angular
/// frequency, for the stability limit. Throws UsageError for dt <= 0, T <= 0,
/// both dt and steps_per_period given, dt above the scheme's limit (unless
/// allow_unstable_steps()), and tolerances out of range.
TimeMesh resolve_time_mesh(const Parameters&, double period, double fastest_w);

}  // namespace vibra
