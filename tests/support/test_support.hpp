// Test helpers: a model's trajectory from KEY=VALUE settings, its rows, and Hermite values computed independently.
#pragma once
#include <Eigen/Dense>
#include <cmath>
#include <cstdio>
#include <memory>
#include <utility>
#include <string>
#include <vector>

#include "core/models/model.hpp"

namespace vibra::test {

/// A model's trajectory with the given KEY=VALUE settings.
inline std::unique_ptr<Trajectory> trajectory(const std::string& model, const std::vector<std::string>& settings) {
  return find_model(model).build(model_settings(model, settings));
}

/// All rows of a (short) trajectory.
inline std::vector<std::vector<double>> rows(Trajectory& t) {
  std::vector<std::vector<double>> out;
  do {
    out.emplace_back(t.width());
    t.row(out.back());
  } while (t.advance());
  return out;
}

inline std::string str(double x) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

/// u and v at time t between two samples {t, u, v, ...} of a scalar
/// second-order ODE whose accelerations there are acc_a and acc_b, computed
/// without core/math/hermite.hpp: the quintic matching u, u' = v and u'' at both
/// ends, its six coefficients solved for, and for v the cubic matching v and
/// v' = u'' at both ends. Errors O(dt^6) in u and O(dt^4) in v: a
/// trajectory's rows between its samples must equal these to rounding, not
/// merely come near the exact solution.
inline std::pair<double, double> quintic_between(const std::vector<double>& a, double acc_a,
                                                 const std::vector<double>& b, double acc_b, double t) {
  const double h = b[0] - a[0], s = (t - a[0]) / h;
  // p(s) = sum c_k s^k on [0, 1], with p' = h u' and p'' = h^2 u''.
  Eigen::Matrix<double, 6, 6> m = Eigen::Matrix<double, 6, 6>::Zero();
  Eigen::Matrix<double, 6, 1> rhs;
  for (int end = 0; end < 2; ++end) {
    const double x = end;
    for (int k = 0; k < 6; ++k) {
      m(3 * end, k) = std::pow(x, k);
      m(3 * end + 1, k) = k >= 1 ? k * std::pow(x, k - 1) : 0;
      m(3 * end + 2, k) = k >= 2 ? k * (k - 1) * std::pow(x, k - 2) : 0;
    }
    const auto& sample = end ? b : a;
    rhs(3 * end) = sample[1];
    rhs(3 * end + 1) = h * sample[2];
    rhs(3 * end + 2) = h * h * (end ? acc_b : acc_a);
  }
  const Eigen::Matrix<double, 6, 1> c = m.fullPivLu().solve(rhs);
  double u = 0;
  for (int k = 0; k < 6; ++k) u += c(k) * std::pow(s, k);
  // v: the cubic through v and v' = u'' at both ends (Hermite basis).
  const double h00 = (1 + 2 * s) * (1 - s) * (1 - s), h10 = s * (1 - s) * (1 - s);
  const double h01 = s * s * (3 - 2 * s), h11 = s * s * (s - 1);
  const double v = h00 * a[2] + h10 * h * acc_a + h01 * b[2] + h11 * h * acc_b;
  return {u, v};
}

}  // namespace vibra::test
