// A convergence study of one model and scheme, as vibra analyze convergence runs it.
#pragma once
#include <string>
#include <vector>

#include "core/analysis/convergence.hpp"

namespace vibra {

/// A convergence study of one model and scheme, as `vibra analyze convergence` runs it.
struct ModelConvergence {
  std::string scheme;  ///< the scheme's name
  int order;           ///< its theoretical rate on this problem (damped_order with velocity damping)
  std::vector<ConvergenceLevel> levels;
  bool settled = false;  ///< the last two rates agree (rates_settled)
};

/// Levels when none are asked for: from kAutoMinLevels, halving dt until the
/// rates settle, at most kAutoMaxLevels.
constexpr int kAutoMinLevels = 4, kAutoMaxLevels = 14;

/// Errors and rates for dt_i = dt_0 2^-i, i = 0..levels-1, where dt_0 is the
/// model's dt with the user's settings (KEY=VALUE), against its exact
/// solution. `levels` 0: as many as the rates need to settle (kAutoMinLevels
/// to kAutoMaxLevels). Throws UsageError for 1 or more than 20 levels, and
/// when the model has no exact solution with these settings (saying which do).
ModelConvergence model_convergence(const std::string& model, const std::vector<std::string>& settings, int levels);

}  // namespace vibra
