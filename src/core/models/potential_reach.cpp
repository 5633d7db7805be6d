// How far a conservative oscillator can swing: where its potential first reaches its energy.
#include "core/models/potential_reach.hpp"

#include <algorithm>
#include <cmath>

namespace vibra {

double potential_reach(const std::function<double(double)>& potential, double u0, double E0, double step) {
  double largest = 0;
  for (double side : {1.0, -1.0}) {
    double below = 0, above = step;
    while (potential(u0 + side * above) < E0) {
      below = above, above *= 2;
      if (above > 1e6 * step) return 0;
    }
    for (int i = 0; i < 60; ++i) {
      const double mid = 0.5 * (below + above);
      (potential(u0 + side * mid) < E0 ? below : above) = mid;
    }
    largest = std::max(largest, std::abs(u0 + side * above));
  }
  return largest;
}

}  // namespace vibra
