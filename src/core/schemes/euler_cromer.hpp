// The Euler-Cromer scheme (1.90)-(1.91).
#pragma once
#include "core/second_order_system.hpp"

namespace vibra {

/// Euler-Cromer (1.90)-(1.91), the semi-implicit Euler method:
/// v^{n+1} = v^n + dt a(u^n, v^n, t_n), u^{n+1} = u^n + dt v^{n+1}. First order.
/// With `half_step_start` the first velocity update uses dt/2, which makes the
/// scheme identical to the centered one for undamped problems (second order);
/// the stored velocity then lives at t_{n-1/2}, so the reported v^n adds half
/// a step of acceleration to keep it second order.
template <int D>
class EulerCromer {
 public:
  EulerCromer(const SecondOrderSystem<D>& system, const Vec<D>& u0, const Vec<D>& v0, double dt,
              bool half_step_start = false)
      : sys_(&system), dt_(dt), half_step_start_(half_step_start), u_(u0), v_(v0) {}

  Sample<D> current() const {
    const double t = n_ * dt_;
    if (!half_step_start_ || n_ == 0) return {t, u_, v_};
    return {t, u_, v_ + 0.5 * dt_ * sys_->acceleration(u_, v_, t)};
  }

  void step() {
    const double h = (half_step_start_ && n_ == 0) ? 0.5 * dt_ : dt_;
    v_ += h * sys_->acceleration(u_, v_, n_ * dt_);
    u_ += dt_ * v_;
    ++n_;
  }

 private:
  const SecondOrderSystem<D>* sys_;
  double dt_;
  bool half_step_start_;
  long long n_ = 0;
  Vec<D> u_, v_;
};

}  // namespace vibra
