// SecondOrderSystem<D>: u'' = force(u, t) plus damping, the equations every scheme steps.
#pragma once
#include <cmath>
#include <functional>

#include "core/sample.hpp"

namespace vibra {

/// How the damping force f(u') depends on the velocity.
enum class Damping { none, linear, quadratic };

/// u'' = force(u, t) + damping, i.e. the generalized model (1.71)
/// m u'' + f(u') + s(u) = F(t) divided by m. The damping is kept apart from
/// the velocity-free force because the centered and staggered schemes treat
/// it implicitly (1.77), (1.84), (1.99)-(1.104). Quadratic damping uses the
/// length of the velocity vector: f = c |v| v (air drag).
template <int D>
struct SecondOrderSystem {
  /// The velocity-free force per unit mass, (F(t) - s(u)) / m. The two laws
  /// that most runs use are inlined into the steppers (a std::function call
  /// would cost as much as the sine itself); anything else is a function.
  enum class Law { spring, sine, general };
  Law law = Law::general;
  double stiffness = 0;  ///< spring: -stiffness u; sine: -stiffness sin(u)
  std::function<Vec<D>(const Vec<D>& u, double t)> general_force;

  Vec<D> force(const Vec<D>& u, double t) const {
    switch (law) {
      case Law::spring: return -stiffness * u;
      case Law::sine:
        if constexpr (D == 1) return Vec<D>(-stiffness * std::sin(u[0]));
        else return -stiffness * u.array().sin().matrix();
      case Law::general: break;
    }
    return general_force(u, t);
  }

  static SecondOrderSystem spring(double k) { return {Law::spring, k, {}}; }
  static SecondOrderSystem sine(double k) { return {Law::sine, k, {}}; }
  static SecondOrderSystem general(std::function<Vec<D>(const Vec<D>&, double)> f) {
    return {Law::general, 0, std::move(f)};
  }

  Damping damping = Damping::none;
  /// b / m: linear damping in 1/time, quadratic in 1/length.
  double damping_per_mass = 0;

  /// The damping's acceleration -f(v)/m.
  Vec<D> damping_acceleration(const Vec<D>& v) const {
    switch (damping) {
      case Damping::linear: return -damping_per_mass * v;
      case Damping::quadratic: return -damping_per_mass * magnitude<D>(v) * v;
      case Damping::none: break;
    }
    return Vec<D>::Zero();
  }

  Vec<D> acceleration(const Vec<D>& u, const Vec<D>& v, double t) const {
    return force(u, t) + damping_acceleration(v);
  }

  /// Solves v = rhs + h * damping_acceleration(v) for v in closed form: the
  /// implicit damping update used by velocity Verlet.
  Vec<D> solve_implicit_damping(const Vec<D>& rhs, double h) const {
    const double c = h * damping_per_mass;
    switch (damping) {
      case Damping::linear: return rhs / (1 + c);
      // v parallel to rhs with |v| + c|v|^2 = |rhs|; the root in a form
      // without cancellation.
      case Damping::quadratic: return rhs * (2 / (1 + std::sqrt(1 + 4 * c * magnitude<D>(rhs))));
      case Damping::none: break;
    }
    return rhs;
  }
};

}  // namespace vibra
