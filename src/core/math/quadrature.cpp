// Adaptive Gauss-Kronrod quadrature (7/15 points), for potentials of formula restoring forces.
#include "core/math/quadrature.hpp"

#include <algorithm>
#include <cmath>

namespace vibra {

namespace {
// Nodes and weights of the 15-point Kronrod rule and its embedded 7-point
// Gauss rule on [-1, 1] (QUADPACK's qk15); the Gauss nodes are the odd ones.
constexpr double kNodes[8] = {0.991455371120812639206854697526329, 0.949107912342758524526189684047851,
                              0.864864423359769072789712788640926, 0.741531185599394439863864773280788,
                              0.586087235467691130294144845693013, 0.405845151377397166906606412076961,
                              0.207784955007898467600689403773245, 0.0};
constexpr double kKronrod[8] = {0.022935322010529224963732008058970, 0.063092092629978553290700663189204,
                                0.104790010322250183839876322541518, 0.140653259715525918745189590510238,
                                0.169004726639267902826583426598550, 0.190350578064785409913256402421014,
                                0.204432940075298892414161999234649, 0.209482141084727828012999174891714};
constexpr double kGauss[4] = {0.129484966168869693270611432679082, 0.279705391489276667901467771423780,
                              0.381830050505118944950369775488975, 0.417959183673469387755102040816327};

struct Estimate {
  double kronrod, gauss;
  double magnitude;  ///< the Kronrod rule applied to |f|: the scale rounding errors are measured against
};

Estimate gauss_kronrod(const std::function<double(double)>& f, double a, double b) {
  const double centre = 0.5 * (a + b), half = 0.5 * (b - a);
  const double fc = f(centre);
  double kronrod = kKronrod[7] * fc, gauss = kGauss[3] * fc, magnitude = kKronrod[7] * std::abs(fc);
  for (int i = 0; i < 7; ++i) {
    const double left = f(centre - half * kNodes[i]), right = f(centre + half * kNodes[i]);
    kronrod += kKronrod[i] * (left + right);
    magnitude += kKronrod[i] * (std::abs(left) + std::abs(right));
    if (i % 2 == 1) gauss += kGauss[i / 2] * (left + right);
  }
  return {kronrod * half, gauss * half, magnitude * std::abs(half)};
}

/// Halves [a, b] until the rules agree to `tolerance` (absolute). `budget`
/// counts the halvings left, so an integrand that is not smooth (a kink, a
/// singularity) costs bounded work and gets the best estimate reached.
double adapt(const std::function<double(double)>& f, double a, double b, const Estimate& whole, double tolerance,
             int& budget) {
  if (std::abs(whole.kronrod - whole.gauss) <= tolerance || budget <= 0 || !std::isfinite(whole.kronrod))
    return whole.kronrod;
  --budget;
  const double middle = 0.5 * (a + b);
  return adapt(f, a, middle, gauss_kronrod(f, a, middle), 0.5 * tolerance, budget) +
         adapt(f, middle, b, gauss_kronrod(f, middle, b), 0.5 * tolerance, budget);
}
}  // namespace

double integrate(const std::function<double(double)>& f, double a, double b, double relative_tolerance) {
  if (a == b) return 0;
  const Estimate whole = gauss_kronrod(f, a, b);
  // |K15 - G7| overstates the 15-point rule's error by orders of magnitude, so
  // a tolerance at the level of rounding still ends after a few halvings. It
  // is relative to the integral of |f|, as rounding is when f changes sign.
  const double tolerance = std::max(relative_tolerance * whole.magnitude, 1e-300);
  int budget = 200;
  return adapt(f, a, b, whole, tolerance, budget);
}

}  // namespace vibra
