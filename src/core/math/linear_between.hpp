// The state of a fixed-step run between two mesh points: the mesh values joined by straight lines.
#pragma once
#include "core/sample.hpp"

namespace vibra {

/// The state at time t between mesh points a and b, u and v each on the
/// straight line between their mesh values. A fixed-step scheme computes
/// nothing between t_n and t_{n+1}: drawn this way, a curve has exactly the
/// extrema its mesh values have (the book's figures join mesh values by
/// straight lines), and a coarse run is not smoothed into motion it does not
/// have. Adaptive schemes interpolate by their own dense output instead
/// (core/math/hermite.hpp). t is clamped to [a.t, b.t].
template <int D>
Sample<D> linear_between(const Sample<D>& a, const Sample<D>& b, double t) {
  const double h = b.t - a.t;
  if (h <= 0 || t >= b.t) return b;
  if (t <= a.t) return a;
  const double s = (t - a.t) / h;
  return {t, a.u + s * (b.u - a.u), a.v + s * (b.v - a.v)};
}

}  // namespace vibra
