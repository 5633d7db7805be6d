// The schemes as one std::variant: names, kinds (fixed, adaptive) and stability limits.
#include "core/scheme.hpp"

#include <cmath>

#include "core/error.hpp"
#include "core/input/name_spelling.hpp"

namespace vibra {

const std::vector<SchemeInfo>& all_schemes() {
  static const std::vector<SchemeInfo> schemes = {
      {Scheme::centered, "centered", 2, "centered differences (1.7), the book's main scheme", false,
       R"(u^{n+1} = 2u^n - u^{n-1} + \Delta t^2 a^n)"},
      {Scheme::centered_adjusted, "centered-adjusted", 4, "centered with w(1 - w^2 dt^2/24) (undamped only)", false,
       R"(u^{n+1} = 2u^n - u^{n-1} - \Delta t^2\omega_a^2 u^n \\ \omega_a = \omega(1 - \omega^2\Delta t^2/24))"},
      {Scheme::backward_damping, "backward-damping", 1, "centered, damping by a backward difference (Problem 1.20)", false,
       R"(u^{n+1} = 2u^n - u^{n-1} + \Delta t^2 a(u^n, \frac{u^n - u^{n-1}}{\Delta t}, t_n))"},
      {Scheme::euler_cromer, "euler-cromer", 1, "Euler-Cromer / semi-implicit Euler (1.54)-(1.55)", false,
       R"(v^{n+1} = v^n + \Delta t\, a^n \\ u^{n+1} = u^n + \Delta t\, v^{n+1})"},
      {Scheme::euler_cromer_half, "euler-cromer-half", 2, "Euler-Cromer with the half-step start v^1 = V + dt/2 a", false,
       R"(v^{n+1/2} = v^{n-1/2} + \Delta t\, a^n \\ u^{n+1} = u^n + \Delta t\, v^{n+1/2} \\ v^{1/2} = V + \frac{\Delta t}{2} a^0)"},
      {Scheme::staggered, "staggered", 2, "staggered mesh / Stormer-Verlet (1.67)-(1.70)", false,
       R"(v^{n+1/2} = v^{n-1/2} + \Delta t\, a^n \\ u^{n+1} = u^n + \Delta t\, v^{n+1/2})"},
      {Scheme::velocity_verlet, "velocity-verlet", 2, "velocity Verlet (Problem 1.6)", false,
       R"(u^{n+1} = u^n + \Delta t\, v^n + \frac{1}{2}\Delta t^2 a^n \\ v^{n+1} = v^n + \frac{1}{2}\Delta t(a^n + a^{n+1}))"},
      {Scheme::pefrl, "pefrl", 4, "PEFRL 4th-order symplectic splitting (1.107)-(1.118)", false,
       R"(u_1 = u^n + \xi\Delta t\, v^n,\; v_1 = v^n + \frac{1 - 2\lambda}{2}\Delta t\, a(u_1) \\ \ldots\; u^{n+1} = u_4 + \xi\Delta t\, v^{n+1})"},
      {Scheme::rk2, "rk2", 2, "2nd-order Runge-Kutta (midpoint)", false,
       R"(k_1 = f(y^n),\; k_2 = f(y^n + \frac{\Delta t}{2}k_1) \\ y^{n+1} = y^n + \Delta t\, k_2)"},
      {Scheme::rk3, "rk3", 3, "3rd-order Runge-Kutta (Kutta's rule, Odespy's RK3)", false,
       R"(y^{n+1} = y^n + \frac{\Delta t}{6}(k_1 + 4k_2 + k_3))"},
      {Scheme::rk4, "rk4", 4, "classical 4th-order Runge-Kutta", false,
       R"(y^{n+1} = y^n + \frac{\Delta t}{6}(k_1 + 2k_2 + 2k_3 + k_4))"},
      {Scheme::forward_euler, "forward-euler", 1, "Forward Euler", false,
       R"(u^{n+1} = u^n + \Delta t\, v^n \\ v^{n+1} = v^n + \Delta t\, a^n)"},
      {Scheme::backward_euler, "backward-euler", 1, "Backward Euler (Newton per step)", false,
       R"(u^{n+1} = u^n + \Delta t\, v^{n+1} \\ v^{n+1} = v^n + \Delta t\, a^{n+1})"},
      {Scheme::crank_nicolson, "crank-nicolson", 2, "Crank-Nicolson (Newton per step)", false,
       R"(u^{n+1} = u^n + \frac{\Delta t}{2}(v^n + v^{n+1}) \\ v^{n+1} = v^n + \frac{\Delta t}{2}(a^n + a^{n+1}))"},
      {Scheme::ab2, "ab2", 2, "2nd-order Adams-Bashforth, started with RK4", false,
       R"(y^{n+1} = y^n + \frac{\Delta t}{2}(3f^n - f^{n-1}))"},
      {Scheme::ab3, "ab3", 3, "3rd-order Adams-Bashforth, started with RK4", false,
       R"(y^{n+1} = y^n + \frac{\Delta t}{12}(23f^n - 16f^{n-1} + 5f^{n-2}))"},
      {Scheme::backward2step, "backward2step", 2, "two-step backward difference BDF2 (Newton per step)", false,
       R"(y^{n+1} = \frac{4}{3}y^n - \frac{1}{3}y^{n-1} + \frac{2}{3}\Delta t\, f^{n+1})"},
      {Scheme::rkf45, "rkf45", 5, "adaptive Runge-Kutta-Fehlberg 4(5): steps from rtol, atol", true,
       R"(y^{n+1} = y^n + \Delta t\sum_{i=1}^{6} b_i k_i \\ \text{Fehlberg 4(5): } \Delta t \text{ from rtol, atol})"},
      {Scheme::dopri5, "dopri5", 5, "adaptive Dormand-Prince 5(4), dense output: steps from rtol, atol", true,
       R"(y^{n+1} = y^n + \Delta t\sum_{i=1}^{7} b_i k_i \\ \text{Dormand-Prince 5(4): } \Delta t \text{ from rtol, atol})"},
  };
  return schemes;
}

int damped_order(const SchemeInfo& info) {
  // Both take a(u, v) at a velocity half a step or more behind (docs/schemes.md).
  static constexpr Scheme kFirstOrderWithDamping[] = {Scheme::euler_cromer_half, Scheme::pefrl};
  for (Scheme s : kFirstOrderWithDamping)
    if (info.scheme == s) return 1;
  return info.order;
}

std::string summary_with_damped_order(const SchemeInfo& info) {
  const int damped = damped_order(info);
  return std::string(info.summary) +
         (damped == info.order ? "" : " (order " + std::to_string(damped) + " with damping)");
}

const SchemeInfo& scheme_info(Scheme scheme) {
  for (const auto& info : all_schemes())
    if (info.scheme == scheme) return info;
  return all_schemes().front();
}

Scheme parse_scheme(std::string_view name) {
  std::string names;
  for (const auto& info : all_schemes()) {
    if (same_name(info.name, name)) return info.scheme;
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
