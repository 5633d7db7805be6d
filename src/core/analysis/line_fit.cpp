// A least-squares straight line y = intercept + slope x.
#include "core/analysis/line_fit.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

namespace vibra {

Line fit_line(const std::vector<double>& x, const std::vector<double>& y) {
  const Eigen::Index n = static_cast<Eigen::Index>(x.size());
  Eigen::MatrixXd A(n, 2);
  Eigen::VectorXd b(n);
  for (Eigen::Index i = 0; i < n; ++i) A(i, 0) = 1, A(i, 1) = x[i], b(i) = y[i];
  const Eigen::Vector2d c = A.colPivHouseholderQr().solve(b);
  return {c(0), c(1)};
}

double largest_residual(const Line& line, const std::vector<double>& x, const std::vector<double>& y) {
  double worst = 0;
  for (size_t i = 0; i < x.size(); ++i) worst = std::max(worst, std::abs(y[i] - line(x[i])));
  return worst;
}

}  // namespace vibra
