// Empirical periods and amplitudes from the extrema of a sampled solution.
#pragma once
#include <deque>
#include <optional>
#include <vector>

#include "core/trajectory.hpp"

namespace vibra {

/// Where an extremum is placed in time.
enum class ExtremumTiming {
  mesh,    ///< at the mesh point t_n, as the book's code does: periods are multiples of dt
  fitted,  ///< by a sinusoid through the three samples around it (a parabola where none fits)
};

/// One cycle of an oscillation: the i-th maximum with its local period and amplitude.
struct OscillationCycle {
  int i;             ///< 0, 1, ...
  double t;          ///< time of the i-th maximum
  double period;     ///< p_i = t_max[i+1] - t_max[i]
  double amplitude;  ///< a_i = |u_max[i] - u_min[i]| / 2
};

/// Local periods and amplitudes of an oscillation from its extrema (docs/analysis.md),
/// fed one sample at a time in constant memory: maxima where
/// u^{n-1} < u^n > u^{n+1}, minima the other way round.
///
/// With fitted timing a sinusoid A cos(theta s + phi) through the three samples
/// places the extremum between mesh points. It is exact for the centered
/// scheme, whose discrete solution is a sinusoid of frequency w~ (1.20), so the
/// periods come out as 2 pi / w~ instead of jumping between multiples of dt.
class EmpiricalOscillation {
 public:
  explicit EmpiricalOscillation(ExtremumTiming timing = ExtremumTiming::fitted) : timing_(timing) {}

  /// The next sample (equally spaced in t); returns the cycle it completes, if any.
  std::optional<OscillationCycle> add(double t, double u);

 private:
  struct Extremum {
    double t, u;
  };
  Extremum locate(double dt) const;

  ExtremumTiming timing_;
  double t_[3] = {0, 0, 0}, u_[3] = {0, 0, 0};  ///< the last three samples, oldest first
  int samples_ = 0;
  std::deque<Extremum> maxima_, minima_;  ///< extrema not yet in a cycle (two at most)
  int cycles_ = 0;
};

/// Every cycle of a trajectory's main quantity (column 1); memory grows with
/// the number of periods, not of steps.
std::vector<OscillationCycle> oscillation_cycles(Trajectory&, ExtremumTiming = ExtremumTiming::fitted);

}  // namespace vibra
