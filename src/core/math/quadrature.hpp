// Adaptive Gauss-Kronrod quadrature (7/15 points), for potentials of formula restoring forces.
#pragma once
#include <functional>

namespace vibra {

/// The integral of f over [a, b] by adaptive Gauss-Kronrod (7-point Gauss,
/// 15-point Kronrod): an interval is halved until the two rules agree to
/// `relative_tolerance` of the running total. The 15-point rule is exact for
/// polynomials up to degree 22, so a polynomial integrand costs one pass; a
/// smooth one reaches ~1e-15 relative in a few. b < a gives minus the integral
/// over [b, a].
double integrate(const std::function<double(double)>& f, double a, double b, double relative_tolerance = 1e-14);

}  // namespace vibra
