// The state between two samples by Hermite interpolation, for adaptive runs without dense output.
#pragma once
#include "core/sample.hpp"

namespace vibra {

/// The state at time t between samples a and b: u by quintic Hermite
/// interpolation through u, u' = v and u'' = acceleration at both ends (6th
/// order), v by cubic Hermite through v and v' = acceleration (4th order).
/// The two are kept apart because a low-order scheme's v is not u's slope
/// (Forward Euler's u_{n+1} - u_n = dt v_n): tying v to u's derivative would
/// make it wiggle between steps. Both are far below any scheme's own error
/// and a pixel, so that a quantity as small as an orbit's radius drift
/// (1e-8) reads the same between steps as at them. Exact while u is a
/// quintic in t and v a cubic (free fall between two impacts, for instance).
/// t is clamped to [a.t, b.t].
template <int D>
Sample<D> hermite_between(const Sample<D>& a, const Vec<D>& acc_a, const Sample<D>& b, const Vec<D>& acc_b,
                          double t) {
  const double h = b.t - a.t;
  if (h <= 0 || t >= b.t) return b;
  if (t <= a.t) return a;
  const double s = (t - a.t) / h, s2 = s * s, s3 = s2 * s, s4 = s3 * s, s5 = s4 * s;
  // The quintic basis for u(a), u'(a), u''(a), u(b), u'(b), u''(b).
  const double q0 = 1 - 10 * s3 + 15 * s4 - 6 * s5, q1 = s - 6 * s3 + 8 * s4 - 3 * s5,
               q2 = 0.5 * (s2 - 3 * s3 + 3 * s4 - s5), q3 = 10 * s3 - 15 * s4 + 6 * s5,
               q4 = -4 * s3 + 7 * s4 - 3 * s5, q5 = 0.5 * (s3 - 2 * s4 + s5);
  // The cubic basis for v(a), v'(a), v(b), v'(b).
  const double c0 = 2 * s3 - 3 * s2 + 1, c1 = s3 - 2 * s2 + s, c2 = -2 * s3 + 3 * s2, c3 = s3 - s2;
  return {t, q0 * a.u + q1 * h * a.v + q2 * h * h * acc_a + q3 * b.u + q4 * h * b.v + q5 * h * h * acc_b,
          c0 * a.v + c1 * h * acc_a + c2 * b.v + c3 * h * acc_b};
}

}  // namespace vibra
