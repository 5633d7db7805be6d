#pragma once
#include "core/sample.hpp"

namespace vibra {

/// The state at time t between samples a and b by cubic Hermite
/// interpolation of u (through u and u' = v) and of v (through v and
/// v' = acceleration): 4th order, and exact while u is a cubic in t (free
/// fall between two impacts, for instance). t is clamped to [a.t, b.t].
template <int D>
Sample<D> hermite_between(const Sample<D>& a, const Vec<D>& acc_a, const Sample<D>& b, const Vec<D>& acc_b,
                          double t) {
  const double h = b.t - a.t;
  if (h <= 0 || t >= b.t) return b;
  if (t <= a.t) return a;
  const double s = (t - a.t) / h, s2 = s * s, s3 = s2 * s;
  const double h00 = 2 * s3 - 3 * s2 + 1, h10 = s3 - 2 * s2 + s, h01 = -2 * s3 + 3 * s2, h11 = s3 - s2;
  return {t, h00 * a.u + h10 * h * a.v + h01 * b.u + h11 * h * b.v,
          h00 * a.v + h10 * h * acc_a + h01 * b.v + h11 * h * acc_b};
}

}  // namespace vibra
