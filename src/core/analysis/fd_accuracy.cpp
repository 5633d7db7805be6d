// The centered difference's accuracy for u'' (Exercise 1.8): E(p) = 4 sin^2(p/2) / p^2.
#include "core/analysis/fd_accuracy.hpp"

#include <cmath>

namespace vibra {

double fd_accuracy(double p) {
  // sin(p/2)/(p/2) loses nothing near 0, but is 0/0 at it.
  if (std::abs(p) < 1e-8) return 1 - p * p / 12;
  const double ratio = std::sin(p / 2) / (p / 2);
  return ratio * ratio;
}

double fd_accuracy_taylor(double p) {
  const double p2 = p * p;
  return 1 - p2 / 12 + p2 * p2 / 360;
}

}  // namespace vibra
