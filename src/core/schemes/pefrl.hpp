// The PEFRL scheme (1.107)-(1.118): a 4th-order symplectic splitting.
#pragma once
#include "core/second_order_system.hpp"

namespace vibra {

/// The Position Extended Forest-Ruth Like method (1.107)-(1.118): a
/// 4th-order symplectic splitting for damping-free problems. Each force
/// evaluation gets the time of its position sub-step (docs/schemes.md).
template <int D>
class Pefrl {
 public:
  static constexpr double xi = 0.1786178958448091;
  static constexpr double lambda = -0.2123418310626054;
  static constexpr double chi = -0.06626458266981849;

  Pefrl(const SecondOrderSystem<D>& system, const Vec<D>& u0, const Vec<D>& v0, double dt)
      : sys_(&system), dt_(dt), u_(u0), v_(v0) {}

  Sample<D> current() const { return {n_ * dt_, u_, v_}; }

  void step() {
    const double t = n_ * dt_, h = dt_;
    const double outer = 0.5 * (1 - 2 * lambda), middle = 1 - 2 * (chi + xi);
    auto g = [&](const Vec<D>& u, const Vec<D>& v, double tt) { return sys_->acceleration(u, v, tt); };
    double tu = t + xi * h;
    Vec<D> u = u_ + xi * h * v_;
    Vec<D> v = v_ + outer * h * g(u, v_, tu);
    u += chi * h * v;
    tu += chi * h;
    v += lambda * h * g(u, v, tu);
    u += middle * h * v;
    tu += middle * h;
    v += lambda * h * g(u, v, tu);
    u += chi * h * v;
    tu += chi * h;
    v += outer * h * g(u, v, tu);
    u_ = u + xi * h * v;
    v_ = v;
    ++n_;
  }

 private:
  const SecondOrderSystem<D>* sys_;
  double dt_;
  long long n_ = 0;
  Vec<D> u_, v_;
};

}  // namespace vibra
