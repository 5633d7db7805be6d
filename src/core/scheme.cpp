#include "core/scheme.hpp"

#include <cmath>

#include "core/error.hpp"

namespace vibra {

const std::vector<SchemeInfo>& all_schemes() {
  static const std::vector<SchemeInfo> schemes = {
      {Scheme::centered, "centered", 2, "centered differences (1.7), the book's main scheme"},
      {Scheme::centered_adjusted, "centered-adjusted", 4, "centered with w(1 - w^2 dt^2/24) (undamped only)"},
      {Scheme::backward_damping, "backward-damping", 1, "centered, damping by a backward difference (Problem 1.20)"},
      {Scheme::euler_cromer, "euler-cromer", 1, "Euler-Cromer / semi-implicit Euler (1.54)-(1.55)"},
      {Scheme::euler_cromer_half, "euler-cromer-half", 2, "Euler-Cromer with the half-step start v^1 = V + dt/2 a"},
      {Scheme::staggered, "staggered", 2, "staggered mesh / Stormer-Verlet (1.67)-(1.70)"},
      {Scheme::velocity_verlet, "velocity-verlet", 2, "velocity Verlet (Problem 1.6)"},
      {Scheme::pefrl, "pefrl", 4, "PEFRL 4th-order symplectic splitting (1.107)-(1.118)"},
      {Scheme::rk2, "rk2", 2, "2nd-order Runge-Kutta (midpoint)"},
      {Scheme::rk3, "rk3", 3, "3rd-order Runge-Kutta (Kutta's rule, Odespy's RK3)"},
      {Scheme::rk4, "rk4", 4, "classical 4th-order Runge-Kutta"},
      {Scheme::forward_euler, "forward-euler", 1, "Forward Euler"},
      {Scheme::backward_euler, "backward-euler", 1, "Backward Euler (Newton per step)"},
      {Scheme::crank_nicolson, "crank-nicolson", 2, "Crank-Nicolson (Newton per step)"},
      {Scheme::ab2, "ab2", 2, "2nd-order Adams-Bashforth, started with RK4"},
      {Scheme::ab3, "ab3", 3, "3rd-order Adams-Bashforth, started with RK4"},
      {Scheme::backward2step, "backward2step", 2, "two-step backward difference BDF2 (Newton per step)"},
      {Scheme::rkf45, "rkf45", 5, "adaptive Runge-Kutta-Fehlberg 4(5): steps from rtol, atol", true},
      {Scheme::dopri5, "dopri5", 5, "adaptive Dormand-Prince 5(4), dense output: steps from rtol, atol", true},
  };
  return schemes;
}

const SchemeInfo& scheme_info(Scheme scheme) {
  for (const auto& info : all_schemes())
    if (info.scheme == scheme) return info;
  return all_schemes().front();
}

Scheme parse_scheme(std::string_view name) {
  std::string names;
  for (const auto& info : all_schemes()) {
    if (info.name == name) return info.scheme;
    names += (names.empty() ? "" : ", ") + std::string(info.name);
  }
  throw UsageError("unknown scheme '" + std::string(name) + "': choose one of " + names);
}

double stability_limit(Scheme scheme, double w) {
  if (!(w > 0)) return 0;
  switch (scheme) {
    // The centered family is stable for w dt <= 2 (1.23).
    case Scheme::centered:
    case Scheme::centered_adjusted:
    case Scheme::backward_damping:
    case Scheme::euler_cromer:
    case Scheme::euler_cromer_half:
    case Scheme::staggered:
    case Scheme::velocity_verlet: return 2 / w;
    // RK4 is stable on the imaginary axis up to |w dt| = 2 sqrt(2).
    case Scheme::rk4: return 2 * std::sqrt(2.0) / w;
    // RK3 up to sqrt(3), AB3 up to 0.7236 (where its boundary locus crosses
    // the imaginary axis); AB2, like Forward Euler, grows for every dt.
    case Scheme::rk3: return std::sqrt(3.0) / w;
    case Scheme::ab3: return 0.7236 / w;
    default: return 0;
  }
}

}  // namespace vibra
