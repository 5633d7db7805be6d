// The theta-rule: Forward Euler, Crank-Nicolson and Backward Euler for u' = v, v' = a(u, v, t).
#pragma once
#include "core/schemes/newton.hpp"
#include "core/second_order_system.hpp"

namespace vibra {

/// The implicit theta-rule for y = (u, v), y' = F(y, t) = (v, a(u, v, t)):
///   y^{n+1} = y^n + dt (theta F(y^{n+1}, t_{n+1}) + (1 - theta) F(y^n, t_n)),
/// Backward Euler (theta = 1) and Crank-Nicolson (theta = 1/2), each step
/// solved by Newton's method (core/schemes/newton.hpp).
template <int D>
class ThetaMethod {
  using Y = Eigen::Matrix<double, 2 * D, 1>;

 public:
  ThetaMethod(const SecondOrderSystem<D>& system, const Vec<D>& u0, const Vec<D>& v0, double dt,
              double theta)
      : sys_(&system), dt_(dt), theta_(theta) {
    y_ << u0, v0;
  }

  Sample<D> current() const { return {n_ * dt_, y_.template head<D>(), y_.template tail<D>()}; }

  void step() {
    const double t0 = n_ * dt_, t1 = (n_ + 1) * dt_;
    const Y explicit_part = y_ + dt_ * (1 - theta_) * rhs(y_, t0);
    auto residual = [&](const Y& y) -> Y { return y - explicit_part - dt_ * theta_ * rhs(y, t1); };
    y_ = newton_solve<2 * D>(residual, Y(y_ + dt_ * rhs(y_, t0)), n_ + 1, t1);  // from a Forward Euler guess
    ++n_;
  }

 private:
  Y rhs(const Y& y, double t) const { return first_order_rhs<D>(*sys_, y, t); }

  const SecondOrderSystem<D>* sys_;
  double dt_;
  double theta_;
  long long n_ = 0;
  Y y_;
};

}  // namespace vibra
