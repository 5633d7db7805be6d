// The sliding box's law (section 1.12.3): u'' + mu sign(u') + s(u) = 0, with s(u) = tanh(alpha u)/alpha.
#pragma once
#include <cmath>

namespace vibra {

/// The scaled sliding box with Coulomb friction (section 1.12.3, Exercise
/// 1.23): u'' + mu sign(u') + s(u) = 0 with s(u) = tanh(alpha u)/alpha, the
/// linear spring u for alpha = 0. Forces in units of the initial spring
/// force k I. Shared by the solver and the drawing.
struct SlidingBoxLaw {
  double mu = 0.1;   ///< friction mu m g / (k I)
  double alpha = 0;  ///< nonlinearity alpha I; 0 = the linear spring

  double spring(double u) const { return alpha == 0 ? u : std::tanh(alpha * u) / alpha; }  ///< s(u)
  /// Whether the box stays at rest at u: the spring cannot beat static friction.
  bool holds(double u) const { return std::abs(spring(u)) <= mu; }
  /// The friction force at (u, v): -mu sign(v) while sliding; at rest
  /// (v = 0) the static friction that balances the spring, at most mu.
  double friction(double u, double v) const {
    if (v > 0) return -mu;
    if (v < 0) return mu;
    const double s = spring(u);
    return std::abs(s) <= mu ? s : (s > 0 ? mu : -mu);
  }
  /// Potential energy of the spring, integral of s from 0 to u.
  double potential(double u) const {
    return alpha == 0 ? 0.5 * u * u : std::log(std::cosh(alpha * u)) / (alpha * alpha);
  }
};

}  // namespace vibra
