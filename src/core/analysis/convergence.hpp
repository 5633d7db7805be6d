// Convergence studies: errors against dt and the rates between levels.
#pragma once
#include <functional>
#include <memory>
#include <vector>

#include "core/trajectory.hpp"

namespace vibra {

/// One row of a convergence study (docs/analysis.md).
struct ConvergenceLevel {
  double dt;
  double error;  ///< E = sqrt(dt sum_n (u^n - u_e(t_n))^2) over the whole mesh
  double rate;   ///< ln(E_{i-1}/E_i) / ln(dt_{i-1}/dt_i); NaN on the first level
};

/// The discrete L2 error of the main quantity (column 1) against `exact`.
double l2_error(Trajectory&, const std::function<double(double)>& exact);

/// Errors and rates for dt_i = dt0 2^-i, i = 0..levels-1; `make(dt)` builds
/// the trajectory for one time step.
std::vector<ConvergenceLevel> convergence_study(const std::function<std::unique_ptr<Trajectory>(double dt)>& make,
                                                const std::function<double(double)>& exact, double dt0,
                                                int levels);

/// Rates "settle" when the last two agree within this: the errors then follow
/// one power of dt, the asymptotic range where the rate means the order.
constexpr double kSettledRateTolerance = 0.05;

/// Whether the study has at least two rates and the last two agree within
/// kSettledRateTolerance.
bool rates_settled(const std::vector<ConvergenceLevel>&);

/// As convergence_study, but halves dt until the rates settle (at least
/// `min_levels` levels) or `max_levels` levels are done, whichever is first.
std::vector<ConvergenceLevel> convergence_until_settled(
    const std::function<std::unique_ptr<Trajectory>(double dt)>& make, const std::function<double(double)>& exact,
    double dt0, int min_levels, int max_levels);

}  // namespace vibra
