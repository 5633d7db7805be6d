// The schemes as one std::variant: names, kinds (fixed, adaptive) and stability limits.
#pragma once
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "core/schemes/adams_bashforth.hpp"
#include "core/schemes/adaptive_runge_kutta.hpp"
#include "core/schemes/backward2step.hpp"
#include "core/schemes/centered.hpp"
#include "core/schemes/euler_cromer.hpp"
#include "core/schemes/pefrl.hpp"
#include "core/schemes/runge_kutta.hpp"
#include "core/schemes/staggered.hpp"
#include "core/schemes/theta_method.hpp"
#include "core/schemes/velocity_verlet.hpp"

namespace vibra {

enum class Scheme {
  centered,
  centered_adjusted,  ///< centered with w (1 - w^2 dt^2/24): 4th order, `undamped` only
  backward_damping,   ///< centered with backward-difference damping (Problem 1.20)
  euler_cromer,
  euler_cromer_half,  ///< Euler-Cromer with the half-step start
  staggered,
  velocity_verlet,
  pefrl,
  rk2,
  rk3,
  rk4,
  forward_euler,
  backward_euler,
  crank_nicolson,
  ab2,             ///< Adams-Bashforth 2, started with RK4
  ab3,             ///< Adams-Bashforth 3, started with RK4
  backward2step,   ///< BDF2, started with Crank-Nicolson
  rkf45,           ///< adaptive Runge-Kutta-Fehlberg 4(5)
  dopri5,          ///< adaptive Dormand-Prince 5(4) with dense output
};

struct SchemeInfo {
  Scheme scheme;
  std::string_view name;     ///< as typed on the command line
  int order;                 ///< theoretical convergence rate for smooth problems
  std::string_view summary;
  /// Chooses its own steps from rtol and atol: the samples fall at uneven
  /// times, and dt only sets the grid of frames and pages.
  bool adaptive = false;
  /// The update formula in the typesetter's LaTeX subset (docs/schemes.md),
  /// written for u' = v, v' = a(u, v, t) with a^n = a(u^n, v^n, t_n), or for
  /// y' = f(y), y = (u, v); lines separated by \\.
  std::string_view formula = {};
};

/// Every scheme, in the order `--help` lists them.
const std::vector<SchemeInfo>& all_schemes();
/// The rate a scheme converges at where a force depends on the velocity (a
/// dashpot, drag): lower than its order where that force is taken at a
/// velocity behind the step.
int damped_order(const SchemeInfo& info);
/// The summary as help lists it: with the damped order where it is lower.
std::string summary_with_damped_order(const SchemeInfo& info);
const SchemeInfo& scheme_info(Scheme);
/// Throws UsageError naming the valid schemes.
Scheme parse_scheme(std::string_view name);

/// Largest stable dt for a problem whose fastest small oscillation has angular
/// frequency w, or 0 when the scheme has no such limit (implicit schemes;
/// Forward Euler and RK2, which grow slowly for every dt).
double stability_limit(Scheme, double w);

template <int D>
using AnyStepper =
    std::variant<Centered<D>, EulerCromer<D>, Staggered<D>, VelocityVerlet<D>, Pefrl<D>, ForwardEuler<D>,
                 RungeKutta2<D>, RungeKutta3<D>, RungeKutta4<D>, ThetaMethod<D>, AdamsBashforth2<D>,
                 AdamsBashforth3<D>, Backward2Step<D>, RungeKuttaFehlberg<D>, DormandPrince<D>>;

/// The stepper for `scheme`, starting at u(0) = u0, v(0) = v0. The system must
/// outlive the stepper. `centered_adjusted` must already be applied to the
/// system by the model (it changes w); here it is the centered scheme.
/// `control` matters to the adaptive schemes only.
template <int D>
AnyStepper<D> make_stepper(Scheme scheme, const SecondOrderSystem<D>& system, const Vec<D>& u0,
                           const Vec<D>& v0, double dt, const StepControl& control = {}) {
  switch (scheme) {
    case Scheme::centered:
    case Scheme::centered_adjusted: return Centered<D>(system, u0, v0, dt);
    case Scheme::backward_damping: return Centered<D>(system, u0, v0, dt, true);
    case Scheme::euler_cromer: return EulerCromer<D>(system, u0, v0, dt);
    case Scheme::euler_cromer_half: return EulerCromer<D>(system, u0, v0, dt, true);
    case Scheme::staggered: return Staggered<D>(system, u0, v0, dt);
    case Scheme::velocity_verlet: return VelocityVerlet<D>(system, u0, v0, dt);
    case Scheme::pefrl: return Pefrl<D>(system, u0, v0, dt);
    case Scheme::rk2: return RungeKutta2<D>(system, u0, v0, dt);
    case Scheme::rk3: return RungeKutta3<D>(system, u0, v0, dt);
    case Scheme::rk4: return RungeKutta4<D>(system, u0, v0, dt);
    case Scheme::forward_euler: return ForwardEuler<D>(system, u0, v0, dt);
    case Scheme::backward_euler: return ThetaMethod<D>(system, u0, v0, dt, 1.0);
    case Scheme::crank_nicolson: return ThetaMethod<D>(system, u0, v0, dt, 0.5);
    case Scheme::ab2: return AdamsBashforth2<D>(system, u0, v0, dt);
    case Scheme::ab3: return AdamsBashforth3<D>(system, u0, v0, dt);
    case Scheme::backward2step: return Backward2Step<D>(system, u0, v0, dt);
    case Scheme::rkf45: return RungeKuttaFehlberg<D>(system, u0, v0, dt, control);
    case Scheme::dopri5: return DormandPrince<D>(system, u0, v0, dt, control);
  }
  return Centered<D>(system, u0, v0, dt);
}

}  // namespace vibra
