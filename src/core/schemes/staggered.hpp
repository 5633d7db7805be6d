// The staggered mesh scheme (1.67)-(1.70), (1.99)-(1.104): u at t_n, v at t_{n+1/2}.
#pragma once
#include "core/second_order_system.hpp"

namespace vibra {

/// The staggered mesh scheme (Stormer-Verlet, staggered Euler-Cromer),
/// (1.67)-(1.70) and (1.99)-(1.104): u at t_n, v at t_{n+1/2}.
///   v^{n+1/2} = v^{n-1/2} + dt a(u^n, v, t_n),  u^{n+1} = u^n + dt v^{n+1/2}
/// with the damping taken implicitly: linear as the mean of v^{n-1/2} and
/// v^{n+1/2}, quadratic as the geometric mean |v^{n-1/2}| v^{n+1/2}.
/// Start v^{1/2} = V + dt/2 a(I, V, 0) (the general form; docs/misprints.md).
/// The reported v^n is the mean of the two half-step velocities.
template <int D>
class Staggered {
 public:
  Staggered(const SecondOrderSystem<D>& system, const Vec<D>& u0, const Vec<D>& v0, double dt)
      : sys_(&system), dt_(dt), u_(u0) {
    v_ahead_ = v0 + 0.5 * dt * system.acceleration(u0, v0, 0.0);
    v_behind_ = 2 * v0 - v_ahead_;  // so the mean at t_0 is exactly V
  }

  Sample<D> current() const { return {n_ * dt_, u_, 0.5 * (v_behind_ + v_ahead_)}; }

  void step() {
    u_ += dt_ * v_ahead_;
    ++n_;
    v_behind_ = v_ahead_;
    v_ahead_ = advance_velocity(n_ * dt_);
  }

 private:
  Vec<D> advance_velocity(double t) const {
    const Vec<D> f = sys_->force(u_, t);
    const double c = sys_->damping_per_mass;
    switch (sys_->damping) {
      case Damping::linear:
        return (v_behind_ + dt_ * (f - 0.5 * c * v_behind_)) / (1 + 0.5 * c * dt_);
      case Damping::quadratic:
        return (v_behind_ + dt_ * f) / (1 + c * magnitude<D>(v_behind_) * dt_);
      case Damping::none: break;
    }
    return v_behind_ + dt_ * f;
  }

  const SecondOrderSystem<D>* sys_;
  double dt_;
  long long n_ = 0;
  Vec<D> u_, v_behind_, v_ahead_;
};

}  // namespace vibra
