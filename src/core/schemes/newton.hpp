// Newton's method with a finite-difference Jacobian, for the implicit schemes' steps.
#pragma once
#include <Eigen/Dense>
#include <cmath>
#include <string>

#include "core/error.hpp"

namespace vibra {

/// Solves residual(y) = 0 by Newton's method from `guess`, with a centered
/// finite-difference Jacobian: exact for linear problems after one
/// iteration, quadratic convergence otherwise. The implicit schemes' step
/// equation; `step` and `t` only name the step in the error.
template <int N, class Residual>
Eigen::Matrix<double, N, 1> newton_solve(const Residual& residual, Eigen::Matrix<double, N, 1> y, long long step,
                                         double t) {
  using Y = Eigen::Matrix<double, N, 1>;
  for (int iteration = 0;; ++iteration) {
    Eigen::Matrix<double, N, N> jacobian;
    for (int j = 0; j < N; ++j) {
      const double h = 1e-6 * (1 + std::abs(y[j]));
      Y plus = y, minus = y;
      plus[j] += h;
      minus[j] -= h;
      jacobian.col(j) = (residual(plus) - residual(minus)) / (2 * h);
    }
    const Y delta = jacobian.partialPivLu().solve(residual(y));
    y -= delta;
    if (delta.norm() <= 1e-13 * (1 + y.norm())) return y;
    if (iteration == 50 || !y.allFinite())
      throw SolutionError("Newton's method did not converge at step " + std::to_string(step) +
                              " (t = " + std::to_string(t) + "): reduce dt",
                          step, t);
  }
}

/// The first-order form y = (u, v), y' = (v, a(u, v, t)) of a second-order
/// system, for the schemes that work on it as a whole.
template <int D, class System>
Eigen::Matrix<double, 2 * D, 1> first_order_rhs(const System& system, const Eigen::Matrix<double, 2 * D, 1>& y,
                                                double t) {
  Eigen::Matrix<double, 2 * D, 1> f;
  f << y.template tail<D>(), system.acceleration(y.template head<D>(), y.template tail<D>(), t);
  return f;
}

}  // namespace vibra
