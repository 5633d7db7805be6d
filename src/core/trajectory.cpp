// Trajectory: a model's run for observers, rows of columns with the exact solution and the state between samples.
#include "core/trajectory.hpp"

#include <algorithm>

namespace vibra {

int velocity_column(const TrajectoryInfo& info) {
  const auto& c = info.columns;
  const auto named = std::find(c.begin(), c.end(), "v" + c[1]);
  return named != c.end() ? static_cast<int>(named - c.begin()) : 2;
}

}  // namespace vibra
