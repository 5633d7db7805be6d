// Convergence studies: errors against dt and the rates between levels.
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

namespace {
/// Solves with `dt` and appends its error and the rate from the level before.
void add_level(std::vector<ConvergenceLevel>& levels, const std::function<std::unique_ptr<Trajectory>(double dt)>& make,
               const std::function<double(double)>& exact, double dt) {
  auto trajectory = make(dt);
  const double error = l2_error(*trajectory, exact);
  const double rate = levels.empty() ? std::numeric_limits<double>::quiet_NaN()
                                     : std::log(levels.back().error / error) / std::log(levels.back().dt / dt);
  levels.push_back({dt, error, rate});
}
}  // namespace

std::vector<ConvergenceLevel> convergence_study(const std::function<std::unique_ptr<Trajectory>(double dt)>& make,
                                                const std::function<double(double)>& exact, double dt0,
                                                int levels) {
  std::vector<ConvergenceLevel> out;
  double dt = dt0;
  for (int i = 0; i < levels; ++i, dt /= 2) add_level(out, make, exact, dt);
  return out;
}

bool rates_settled(const std::vector<ConvergenceLevel>& levels) {
  if (levels.size() < 3) return false;
  const double last = levels.back().rate, before = levels[levels.size() - 2].rate;
  return std::isfinite(last) && std::isfinite(before) && std::abs(last - before) <= kSettledRateTolerance;
}

std::vector<ConvergenceLevel> convergence_until_settled(
    const std::function<std::unique_ptr<Trajectory>(double dt)>& make, const std::function<double(double)>& exact,
    double dt0, int min_levels, int max_levels) {
  std::vector<ConvergenceLevel> out;
  double dt = dt0;
  for (int i = 0; i < max_levels; ++i, dt /= 2) {
    add_level(out, make, exact, dt);
    if (int(out.size()) >= min_levels && rates_settled(out)) break;
  }
  return out;
}

}  // namespace vibra
