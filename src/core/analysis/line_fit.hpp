// A least-squares straight line y = intercept + slope x.
#pragma once
#include <vector>

namespace vibra {

/// y = intercept + slope x.
struct Line {
  double intercept, slope;
  double operator()(double x) const { return intercept + slope * x; }
};

/// The least-squares line through (x_i, y_i), solved by QR (x may span
/// decades). Needs two distinct x at least.
Line fit_line(const std::vector<double>& x, const std::vector<double>& y);

/// max_i |y_i - line(x_i)|: how far the data stray from the fit.
double largest_residual(const Line&, const std::vector<double>& x, const std::vector<double>& y);

}  // namespace vibra
