#pragma once
#include <vector>

namespace vibra {

/// y = coefficient * x^exponent.
struct PowerLaw {
  double coefficient, exponent;
  double operator()(double x) const;
};

/// The power law through (x_i, y_i), all > 0, by linear least squares on
/// (ln x, ln y). Needs two distinct x at least.
PowerLaw fit_power_law(const std::vector<double>& x, const std::vector<double>& y);

}  // namespace vibra
