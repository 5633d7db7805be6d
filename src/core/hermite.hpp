#pragma once
#include "core/sample.hpp"

namespace vibra {

/// The state at time t between samples a and b by quintic Hermite
/// interpolation of u through u, u' = v and u'' = acceleration at both ends,
/// and v as its derivative: 6th order in u and 5th in v, far below any
/// scheme's own error and below a pixel, so that a quantity as small as an
/// orbit's radius drift (1e-8) reads the same between steps as at them.
/// Exact while u is a quintic in t (free fall between two impacts, for
/// instance). t is clamped to [a.t, b.t].
template <int D>
Sample<D> hermite_between(const Sample<D>& a, const Vec<D>& acc_a, const Sample<D>& b, const Vec<D>& acc_b,
                          double t) {
  const double h = b.t - a.t;
  if (h <= 0 || t >= b.t) return b;
  if (t <= a.t) return a;
  const double s = (t - a.t) / h, s2 = s * s, s3 = s2 * s, s4 = s3 * s, s5 = s4 * s;
  // The basis for u(a), u'(a), u''(a), u(b), u'(b), u''(b), and its derivative in s.
  const double h0 = 1 - 10 * s3 + 15 * s4 - 6 * s5, h1 = s - 6 * s3 + 8 * s4 - 3 * s5,
               h2 = 0.5 * (s2 - 3 * s3 + 3 * s4 - s5), h3 = 10 * s3 - 15 * s4 + 6 * s5,
               h4 = -4 * s3 + 7 * s4 - 3 * s5, h5 = 0.5 * (s3 - 2 * s4 + s5);
  const double d0 = -30 * s2 + 60 * s3 - 30 * s4, d1 = 1 - 18 * s2 + 32 * s3 - 15 * s4,
               d2 = 0.5 * (2 * s - 9 * s2 + 12 * s3 - 5 * s4), d4 = -12 * s2 + 28 * s3 - 15 * s4,
               d5 = 0.5 * (3 * s2 - 8 * s3 + 5 * s4);
  return {t, h0 * a.u + h1 * h * a.v + h2 * h * h * acc_a + h3 * b.u + h4 * h * b.v + h5 * h * h * acc_b,
          d0 / h * (a.u - b.u) + d1 * a.v + d2 * h * acc_a + d4 * b.v + d5 * h * acc_b};
}

}  // namespace vibra
