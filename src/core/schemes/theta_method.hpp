#pragma once
#include <Eigen/Dense>
#include <cmath>
#include <string>

#include "core/error.hpp"
#include "core/second_order_system.hpp"

namespace vibra {

/// The implicit theta-rule for y = (u, v), y' = F(y, t) = (v, a(u, v, t)):
///   y^{n+1} = y^n + dt (theta F(y^{n+1}, t_{n+1}) + (1 - theta) F(y^n, t_n)),
/// Backward Euler (theta = 1) and Crank-Nicolson (theta = 1/2). Each step is
/// solved by Newton's method with a finite-difference Jacobian, which is exact
/// for linear problems after one iteration and converges quadratically
/// otherwise.
template <int D>
class ThetaMethod {
  using Y = Eigen::Matrix<double, 2 * D, 1>;
  using J = Eigen::Matrix<double, 2 * D, 2 * D>;

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
    Y y = y_ + dt_ * rhs(y_, t0);  // Forward Euler predictor
    for (int iteration = 0;; ++iteration) {
      const Y r = residual(y);
      const Y delta = jacobian(residual, y).partialPivLu().solve(r);
      y -= delta;
      if (delta.norm() <= 1e-13 * (1 + y.norm())) break;
      if (iteration == 50 || !y.allFinite())
        throw SolutionError("Newton's method did not converge at step " + std::to_string(n_ + 1) +
                            " (t = " + std::to_string(t1) + "): reduce dt",
                            n_ + 1, t1);
    }
    y_ = y;
    ++n_;
  }

 private:
  Y rhs(const Y& y, double t) const {
    Y f;
    f << y.template tail<D>(), sys_->acceleration(y.template head<D>(), y.template tail<D>(), t);
    return f;
  }

  template <class Residual>
  static J jacobian(const Residual& residual, const Y& y) {
    J jac;
    for (int j = 0; j < 2 * D; ++j) {
      const double h = 1e-6 * (1 + std::abs(y[j]));
      Y plus = y, minus = y;
      plus[j] += h;
      minus[j] -= h;
      jac.col(j) = (residual(plus) - residual(minus)) / (2 * h);
    }
    return jac;
  }

  const SecondOrderSystem<D>* sys_;
  double dt_;
  double theta_;
  long long n_ = 0;
  Y y_;
};

}  // namespace vibra
