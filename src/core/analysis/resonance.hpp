// Steady amplitudes of u'' + beta u' + u = sin(gamma t) measured from runs (Exercise 1.22).
#pragma once
#include <vector>

namespace vibra {

/// One measured steady amplitude of u'' + beta u' + u = sin(gamma t).
struct ResonancePoint {
  double beta, gamma;
  double amplitude;  ///< measured: half the range of u over the last forcing periods
  double exact;      ///< 1 / sqrt((1 - gamma^2)^2 + (beta gamma)^2)
};

/// Exercise 1.22: runs the `resonance` model from rest with RK4 (200 steps per
/// period of the faster of the forcing and the natural oscillation) until the
/// transient e^{-beta t/2} has fallen below 1e-5, then measures half the
/// range of u over 5 forcing periods. beta must be > 0 (without damping there
/// is no steady state).
ResonancePoint measure_steady_amplitude(double beta, double gamma);

}  // namespace vibra
