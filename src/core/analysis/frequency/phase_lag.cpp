// The phase lag of a numerical maximum behind the exact solution's (Exercise 1.2).
#include "core/analysis/frequency/phase_lag.hpp"

#include <cmath>

namespace vibra {

double phase_lag(const std::function<double(double)>& exact, double period, double t_max) {
  // The best of 64 samples over one period about t_max, then golden-section
  // search between its neighbours (one maximum there).
  const int samples = 64;
  const double h = period / samples;
  double best = t_max - period / 2;
  for (int k = 1; k <= samples; ++k) {
    const double t = t_max - period / 2 + k * h;
    if (exact(t) > exact(best)) best = t;
  }
  double a = best - h, b = best + h;
  const double g = (std::sqrt(5.0) - 1) / 2;
  for (int i = 0; i < 100 && b - a > 1e-14 * (1 + std::abs(best)); ++i) {
    const double c = b - g * (b - a), d = a + g * (b - a);
    if (exact(c) > exact(d)) b = d;
    else a = c;
  }
  return 2 * M_PI * (t_max - 0.5 * (a + b)) / period;
}

}  // namespace vibra
