// The two-step backward difference scheme (BDF2) for u' = v, v' = a(u, v, t).
#pragma once
#include "core/schemes/newton.hpp"
#include "core/schemes/theta_method.hpp"

namespace vibra {

/// The two-step backward difference (BDF2, Odespy's Backward2Step) for
/// y = (u, v), y' = f(y, t) = (v, a(u, v, t)):
///   y^{n+1} - 4/3 y^n + 1/3 y^{n-1} = 2/3 dt f(y^{n+1}, t_{n+1}),
/// solved by Newton's method. It damps oscillations slightly (it is
/// A-stable), second order. The first step, with no y^{-1}, is
/// Crank-Nicolson's: second order too, so the start keeps the rate.
template <int D>
class Backward2Step {
  using Y = Eigen::Matrix<double, 2 * D, 1>;

 public:
  Backward2Step(const SecondOrderSystem<D>& system, const Vec<D>& u0, const Vec<D>& v0, double dt)
      : sys_(&system), dt_(dt), starter_(system, u0, v0, dt, 0.5) {
    y_ << u0, v0;
  }

  Sample<D> current() const { return {n_ * dt_, y_.template head<D>(), y_.template tail<D>()}; }

  void step() {
    const Y before = y_;
    if (n_ == 0) {
      starter_.step();
      const Sample<D> s = starter_.current();
      y_ << s.u, s.v;
    } else {
      const double t1 = (n_ + 1) * dt_;
      const Y known = (4 * y_ - previous_) / 3;
      auto residual = [&](const Y& y) -> Y { return y - known - 2 * dt_ / 3 * first_order_rhs<D>(*sys_, y, t1); };
      y_ = newton_solve<2 * D>(residual, Y(2 * y_ - previous_), n_ + 1, t1);  // from the linear extrapolation
    }
    previous_ = before;
    ++n_;
  }

 private:
  const SecondOrderSystem<D>* sys_;
  double dt_;
  ThetaMethod<D> starter_;
  long long n_ = 0;
  Y y_, previous_;
};

}  // namespace vibra
