// The pendulum's exact period 4 K(sin(Theta/2)), K by the arithmetic-geometric mean.
#include "core/analysis/frequency/pendulum_period.hpp"

#include <cmath>

namespace vibra {

double complete_elliptic_k_complementary(double k_prime) {
  if (!(k_prime > 0)) return INFINITY;
  double a = 1, b = k_prime;
  // Quadratic convergence: 6 iterations reach rounding for k' >= 1e-10; the
  // bound only guards against a non-terminating loop.
  for (int i = 0; i < 64 && std::abs(a - b) > 1e-16 * a; ++i) {
    const double mean = 0.5 * (a + b);
    b = std::sqrt(a * b);
    a = mean;
  }
  return M_PI / (a + b);  // pi / (2 AGM) with AGM = (a + b)/2 once they agree
}

double complete_elliptic_k(double k) {
  const double magnitude = std::abs(k);
  if (magnitude >= 1) return INFINITY;
  return complete_elliptic_k_complementary(std::sqrt((1 - magnitude) * (1 + magnitude)));
}

double pendulum_period(double amplitude) {
  const double half = 0.5 * std::abs(amplitude);
  if (half >= 0.5 * M_PI) return INFINITY;
  return 4 * complete_elliptic_k_complementary(std::cos(half));  // k = sin(amplitude/2), k' = cos(amplitude/2)
}

}  // namespace vibra
