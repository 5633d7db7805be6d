#include "core/analysis/power_law_fit.hpp"

#include <Eigen/Dense>
#include <cmath>

namespace vibra {

double PowerLaw::operator()(double x) const { return coefficient * std::pow(x, exponent); }

PowerLaw fit_power_law(const std::vector<double>& x, const std::vector<double>& y) {
  const Eigen::Index n = static_cast<Eigen::Index>(x.size());
  Eigen::MatrixXd A(n, 2);
  Eigen::VectorXd b(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    A(i, 0) = 1;
    A(i, 1) = std::log(x[i]);
    b(i) = std::log(y[i]);
  }
  // QR rather than the normal equations: ln x spans decades, and QR keeps the accuracy.
  const Eigen::Vector2d c = A.colPivHouseholderQr().solve(b);
  return {std::exp(c(0)), c(1)};
}

}  // namespace vibra
