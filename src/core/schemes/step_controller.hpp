// The step size controller of the adaptive Runge-Kutta pairs (docs/schemes.md,
// "Adaptive"): whether a step is accepted, the next step size, and the limits
// that end a run which can no longer advance in doubles.
#pragma once
#include <algorithm>
#include <cmath>
#include <limits>

namespace vibra {

/// The controller's constants, as docs/schemes.md states them.
struct StepControllerLimits {
  static constexpr double safety = 0.9;  ///< aim below the tolerance, so that the next step is accepted
  static constexpr double growth = 5;    ///< largest factor from one step to the next
  static constexpr double shrink = 0.2;  ///< smallest factor (also for a non-finite error norm)
  /// Rejected steps in a row that end the run: a step that can be met
  /// is met after a few (each shrinks h by 0.2 to 0.9).
  static constexpr int rejections_in_a_row = 100;
  /// A step shorter than this many spacings of the doubles at t cannot be
  /// told from rounding: the run ends (t + h == t is the extreme).
  static constexpr double spacings_per_step = 10;
};

/// What the controller says of one step's error norm.
struct StepVerdict {
  bool accepted;
  double factor;  ///< the next step size over this one's
};

/// A step is accepted when its error norm is at most 1; the next step is
/// scaled by safety err^(-1/(order+1)), within [shrink, growth], and not
/// grown right after a rejection. A NaN norm (a non-finite stage) shrinks.
template <int order>
StepVerdict judge_step(double error_norm, bool rejected_before) {
  using L = StepControllerLimits;
  double factor = L::safety * std::pow(error_norm, -1.0 / (order + 1));
  if (!(factor >= L::shrink)) factor = L::shrink;
  factor = std::min(factor, rejected_before ? 1.0 : L::growth);
  return {error_norm <= 1, factor};
}

/// The shortest step that still moves t by more than rounding, and no
/// shorter than the smallest normal double (below it h a_ij k_j loses its
/// digits to underflow).
inline double shortest_step(double t) {
  const double spacing = std::nextafter(std::abs(t), std::numeric_limits<double>::infinity()) - std::abs(t);
  return std::max(StepControllerLimits::spacings_per_step * spacing, std::numeric_limits<double>::min());
}

}  // namespace vibra
