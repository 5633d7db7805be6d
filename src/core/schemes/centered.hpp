// The centered scheme (1.7), with damping as in (1.75) and (1.82).
#pragma once
#include "core/second_order_system.hpp"

namespace vibra {

/// The centered scheme (1.7) for u'' = force(u, t) + damping, generalized as
/// (1.75)/(1.82): linear damping by a centered difference, quadratic damping by
/// the geometric mean |u'^{n-1/2}| u'^{n+1/2}. First step (1.77)/(1.84).
/// With `backward_damping` the damping uses the backward difference
/// (u^n - u^{n-1})/dt instead (Problem 1.20; first order).
/// The stepper keeps u^{n+1} ahead so that the velocity at t_n is the centered
/// difference (u^{n+1} - u^{n-1}) / (2 dt) (1.12).
template <int D>
class Centered {
 public:
  Centered(const SecondOrderSystem<D>& system, const Vec<D>& u0, const Vec<D>& v0, double dt,
           bool backward_damping = false)
      : sys_(&system), dt_(dt), half_inverse_dt_(0.5 / dt), backward_damping_(backward_damping), cur_(u0) {
    next_ = u0 + dt * v0 + 0.5 * dt * dt * system.acceleration(u0, v0, 0.0);
    prev_ = next_ - 2 * dt * v0;  // u^{-1} from the centered initial condition
  }

  Sample<D> current() const { return {n_ * dt_, cur_, (next_ - prev_) * half_inverse_dt_}; }

  void step() {
    ++n_;
    prev_ = cur_;
    cur_ = next_;
    next_ = advance(n_ * dt_);
  }

 private:
  [[gnu::always_inline]] Vec<D> advance(double t) const {
    const double dt2 = dt_ * dt_;
    const Vec<D> f = sys_->force(cur_, t);
    if (backward_damping_) {
      const Vec<D> v = (cur_ - prev_) / dt_;
      return 2 * cur_ - prev_ + dt2 * (f + sys_->damping_acceleration(v));
    }
    const double c = sys_->damping_per_mass;
    switch (sys_->damping) {
      case Damping::linear:
        return (2 * cur_ + (0.5 * c * dt_ - 1) * prev_ + dt2 * f) / (1 + 0.5 * c * dt_);
      case Damping::quadratic: {
        const double jump = c * magnitude<D>(cur_ - prev_);
        return (2 * cur_ - prev_ + jump * cur_ + dt2 * f) / (1 + jump);
      }
      case Damping::none: break;
    }
    return 2 * cur_ - prev_ + dt2 * f;
  }

  const SecondOrderSystem<D>* sys_;
  double dt_;
  double half_inverse_dt_;  ///< 1/(2 dt): a multiply per step instead of a divide
  bool backward_damping_;
  long long n_ = 0;
  Vec<D> prev_, cur_, next_;
};

}  // namespace vibra
