// The explicit one-step Runge-Kutta methods: Forward Euler, RK2, RK3 and RK4.
#pragma once
#include "core/second_order_system.hpp"

namespace vibra {

/// The explicit one-step methods for the first-order system u' = v,
/// v' = a(u, v, t): Forward Euler (stages = 1), the midpoint RK2 of the book's
/// Odespy (stages = 2), Odespy's RK3 (Kutta's third-order rule, stages = 3)
/// and the classical RK4 (stages = 4).
template <int D, int Stages>
class RungeKutta {
  static_assert(Stages >= 1 && Stages <= 4);

 public:
  RungeKutta(const SecondOrderSystem<D>& system, const Vec<D>& u0, const Vec<D>& v0, double dt)
      : sys_(&system), dt_(dt), u_(u0), v_(v0) {}

  Sample<D> current() const { return {n_ * dt_, u_, v_}; }

  void step() {
    const double t = n_ * dt_, h = dt_;
    auto a = [&](const Vec<D>& u, const Vec<D>& v, double tt) { return sys_->acceleration(u, v, tt); };
    const Vec<D> a1 = a(u_, v_, t);
    if constexpr (Stages == 1) {
      u_ += h * v_;
      v_ += h * a1;
    } else if constexpr (Stages == 2) {
      const Vec<D> um = u_ + 0.5 * h * v_, vm = v_ + 0.5 * h * a1;
      u_ += h * vm;
      v_ += h * a(um, vm, t + 0.5 * h);
    } else if constexpr (Stages == 3) {
      const Vec<D> u2 = u_ + 0.5 * h * v_, v2 = v_ + 0.5 * h * a1;
      const Vec<D> a2 = a(u2, v2, t + 0.5 * h);
      const Vec<D> u3 = u_ + h * (2 * v2 - v_), v3 = v_ + h * (2 * a2 - a1);
      const Vec<D> a3 = a(u3, v3, t + h);
      u_ += h / 6 * (v_ + 4 * v2 + v3);
      v_ += h / 6 * (a1 + 4 * a2 + a3);
    } else {
      const Vec<D> u2 = u_ + 0.5 * h * v_, v2 = v_ + 0.5 * h * a1;
      const Vec<D> a2 = a(u2, v2, t + 0.5 * h);
      const Vec<D> u3 = u_ + 0.5 * h * v2, v3 = v_ + 0.5 * h * a2;
      const Vec<D> a3 = a(u3, v3, t + 0.5 * h);
      const Vec<D> u4 = u_ + h * v3, v4 = v_ + h * a3;
      const Vec<D> a4 = a(u4, v4, t + h);
      u_ += h / 6 * (v_ + 2 * v2 + 2 * v3 + v4);
      v_ += h / 6 * (a1 + 2 * a2 + 2 * a3 + a4);
    }
    ++n_;
  }

 private:
  const SecondOrderSystem<D>* sys_;
  double dt_;
  long long n_ = 0;
  Vec<D> u_, v_;
};

template <int D>
using ForwardEuler = RungeKutta<D, 1>;
template <int D>
using RungeKutta2 = RungeKutta<D, 2>;
template <int D>
using RungeKutta3 = RungeKutta<D, 3>;
template <int D>
using RungeKutta4 = RungeKutta<D, 4>;

}  // namespace vibra
