// The centered difference's accuracy for u'' (Exercise 1.8): E(p) = 4 sin^2(p/2) / p^2.
#pragma once

namespace vibra {

/// How well the centered difference [DtDt u]^n approximates u'' for
/// u = cos(w t) (Exercise 1.8): E(p) = [DtDt u]/u'' = 4 sin^2(p/2) / p^2 with
/// p = w dt, 1 at p = 0 and below 1 up to p = pi (two steps a period).
double fd_accuracy(double p);

/// E's Taylor polynomial about p = 0 to 4th order, 1 - p^2/12 + p^4/360: the
/// p^2/12 is the scheme's second-order error.
double fd_accuracy_taylor(double p);

}  // namespace vibra
