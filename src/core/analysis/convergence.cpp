#include "core/analysis/convergence.hpp"

#include <cmath>
#include <limits>

namespace vibra {

double l2_error(Trajectory& trajectory, const std::function<double(double)>& exact) {
  std::vector<double> row(trajectory.width());
  double sum = 0;
  do {
    trajectory.row(row);
    const double e = row[1] - exact(row[0]);
    sum += e * e;
  } while (trajectory.advance());
  return std::sqrt(trajectory.info().mesh.dt * sum);
}

std::vector<ConvergenceLevel> convergence_study(const std::function<std::unique_ptr<Trajectory>(double dt)>& make,
                                                const std::function<double(double)>& exact, double dt0,
                                                int levels) {
  std::vector<ConvergenceLevel> out;
  double dt = dt0;
  for (int i = 0; i < levels; ++i, dt /= 2) {
    auto trajectory = make(dt);
    const double error = l2_error(*trajectory, exact);
    const double rate = out.empty() ? std::numeric_limits<double>::quiet_NaN()
                                    : std::log(out.back().error / error) / std::log(out.back().dt / dt);
    out.push_back({dt, error, rate});
  }
  return out;
}

}  // namespace vibra
