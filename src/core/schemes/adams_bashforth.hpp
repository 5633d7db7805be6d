// The explicit Adams-Bashforth methods AB2 and AB3 for u' = v, v' = a(u, v, t).
#pragma once
#include <array>

#include "core/schemes/newton.hpp"
#include "core/schemes/runge_kutta.hpp"

namespace vibra {

/// The explicit Adams-Bashforth methods of the book's Odespy for
/// y = (u, v), y' = f(y, t) = (v, a(u, v, t)), Steps = 2 or 3:
///   AB2: y^{n+1} = y^n + dt/2 (3 f^n - f^{n-1})
///   AB3: y^{n+1} = y^n + dt/12 (23 f^n - 16 f^{n-1} + 5 f^{n-2})
/// The missing history of the first Steps - 1 steps comes from RK4, whose
/// local error is below the method's own, so the start keeps the order.
template <int D, int Steps>
class AdamsBashforth {
  static_assert(Steps == 2 || Steps == 3);
  using Y = Eigen::Matrix<double, 2 * D, 1>;

 public:
  AdamsBashforth(const SecondOrderSystem<D>& system, const Vec<D>& u0, const Vec<D>& v0, double dt)
      : sys_(&system), dt_(dt), starter_(system, u0, v0, dt) {
    y_ << u0, v0;
  }

  Sample<D> current() const { return {n_ * dt_, y_.template head<D>(), y_.template tail<D>()}; }

  void step() {
    for (int i = Steps - 1; i > 0; --i) f_[i] = f_[i - 1];
    f_[0] = first_order_rhs<D>(*sys_, y_, n_ * dt_);
    if (n_ < Steps - 1) {
      starter_.step();
      const Sample<D> s = starter_.current();
      y_ << s.u, s.v;
    } else if constexpr (Steps == 2) {
      y_ += dt_ / 2 * (3 * f_[0] - f_[1]);
    } else {
      y_ += dt_ / 12 * (23 * f_[0] - 16 * f_[1] + 5 * f_[2]);
    }
    ++n_;
  }

 private:
  const SecondOrderSystem<D>* sys_;
  double dt_;
  RungeKutta4<D> starter_;
  long long n_ = 0;
  Y y_;
  std::array<Y, Steps> f_{};  ///< f^n, f^{n-1}, ...
};

template <int D>
using AdamsBashforth2 = AdamsBashforth<D, 2>;
template <int D>
using AdamsBashforth3 = AdamsBashforth<D, 3>;

}  // namespace vibra
