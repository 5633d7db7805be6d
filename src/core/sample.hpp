// Sample: the state of a D-dimensional second-order system at one time.
#pragma once
#include <Eigen/Core>

namespace vibra {

/// Position or velocity of a D-dimensional second-order system
/// (D = 1: u(t); D = 2: the elastic pendulum's or a planet's (x, y)).
template <int D>
using Vec = Eigen::Matrix<double, D, 1>;

/// |v|: the length of a vector, written so that D = 1 costs an abs, not a sqrt.
template <int D>
inline double magnitude(const Vec<D>& v) {
  if constexpr (D == 1) {
    return v[0] < 0 ? -v[0] : v[0];
  } else {
    return v.norm();
  }
}

/// The solution at one mesh point t_n: position u^n and velocity v^n.
template <int D>
struct Sample {
  double t = 0;
  Vec<D> u = Vec<D>::Zero();
  Vec<D> v = Vec<D>::Zero();
};

}  // namespace vibra
