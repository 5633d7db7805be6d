// What a long orbit run's blocks support: a linear phase drift to extrapolate, a bounded energy error, in words.
#pragma once
#include <string>

#include "core/analysis/line_fit.hpp"
#include "core/analysis/orbit_error.hpp"

namespace vibra {

/// How far `vibra analyze orbit --long` extrapolates: 1e9 orbits.
constexpr double kExtrapolatedOrbits = 1e9;

/// The distance between two points of the unit circle `phase` apart.
double chord(double phase);

/// What a long run's data support: a linear phase drift (the line explains
/// the phase errors to within a tenth of the drift it fits over the run) to
/// extrapolate, and a bounded energy error (the second half's largest at
/// most twice the first half's), in a sentence that says how far to trust it.
struct LongRunVerdict {
  Line fit;
  double residual, max_energy_error;
  bool linear;
  std::string text;
};
LongRunVerdict judge_long_run(const OrbitRun& run);

}  // namespace vibra
