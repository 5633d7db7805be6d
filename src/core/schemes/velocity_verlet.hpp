// The Velocity Verlet scheme (Problem 1.6).
#pragma once
#include "core/second_order_system.hpp"

namespace vibra {

/// Velocity Verlet (Problem 1.6): a Taylor step for u, Crank-Nicolson
/// (trapezoidal) for v. The damping at t_{n+1} is solved implicitly in closed
/// form, so the scheme stays second order with linear or quadratic damping.
template <int D>
class VelocityVerlet {
 public:
  VelocityVerlet(const SecondOrderSystem<D>& system, const Vec<D>& u0, const Vec<D>& v0, double dt)
      : sys_(&system), dt_(dt), u_(u0), v_(v0), a_(system.acceleration(u0, v0, 0.0)) {}

  Sample<D> current() const { return {n_ * dt_, u_, v_}; }

  void step() {
    const double t_next = (n_ + 1) * dt_;
    u_ += dt_ * v_ + 0.5 * dt_ * dt_ * a_;
    const Vec<D> f_next = sys_->force(u_, t_next);
    v_ = sys_->solve_implicit_damping(v_ + 0.5 * dt_ * (a_ + f_next), 0.5 * dt_);
    a_ = f_next + sys_->damping_acceleration(v_);
    ++n_;
  }

 private:
  const SecondOrderSystem<D>* sys_;
  double dt_;
  long long n_ = 0;
  Vec<D> u_, v_, a_;
};

}  // namespace vibra
