// The forces of the generalized model (1.71) as the vibration model's keys give them.
#pragma once
#include <cmath>
#include <functional>
#include <memory>
#include <optional>

#include "core/input/expression.hpp"
#include "core/input/parameters.hpp"
#include "core/second_order_system.hpp"

namespace vibra {

/// The forces of the generalized model (1.71), m u'' + f(u') + s(u) = F(t),
/// as the `vibration` model's keys give them. The solver and the drawings
/// read the same law, so the arrows drawn are the forces solved.
struct VibrationLaw {
  double mass = 1;
  double b = 0;                  ///< damping coefficient
  Damping damping = Damping::none;
  double k = 1;                  ///< linear spring stiffness, when s is not a formula
  std::optional<Expression> s;   ///< the restoring force as a formula in u
  std::optional<Expression> F;   ///< the external force as a formula in t; none when F = 0

  /// Reads m, b, damping, k or s, and F; throws UsageError for b < 0, m <= 0,
  /// or k and s given together.
  static VibrationLaw from(const Parameters&);

  double spring(double u) const { return s ? (*s)(u) : k * u; }  ///< s(u)
  double damper(double v) const {                                ///< f(v)
    switch (damping) {
      case Damping::linear: return b * v;
      case Damping::quadratic: return b * std::abs(v) * v;
      case Damping::none: break;
    }
    return 0;
  }
  double external(double t) const { return F ? (*F)(t) : 0; }  ///< F(t)
  /// s'(0), the stiffness of small oscillations about u = 0.
  double small_oscillation_stiffness() const;
  /// The potential energy P(u) = integral of s from 0 to u (exact for the linear spring).
  bool linear_spring() const { return !s; }
  /// The system u'' = (F(t) - s(u))/m - f(u')/m that the schemes step.
  std::shared_ptr<SecondOrderSystem<1>> system() const;
  /// A forcing formula, or none when it is written as 0.
  static std::optional<Expression> unless_zero(const Expression&);
};

/// The exact solution of the linear spring without forcing (docs/models.md):
/// undamped, or underdamped linear damping, zeta = b / (2 sqrt(k m)) < 1;
/// empty otherwise.
std::function<double(double)> free_linear_solution(const VibrationLaw&, double I, double V);

/// The exact solution of the undamped linear spring forced by a sine,
/// m u'' + k u = A sin(phi t) (Exercise 1.12), with F written as
/// `A*sin(phi*t)`, `sin(phi*t)` or `A*sin(t)` (A and phi constant
/// expressions); at resonance, phi = w, the secular term -A t cos(w t)/(2 m w).
/// Empty for any other law or force.
std::function<double(double)> sine_forced_solution(const VibrationLaw&, double I, double V);

}  // namespace vibra
