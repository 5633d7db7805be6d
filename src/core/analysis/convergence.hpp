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

}  // namespace vibra
