// The rows a figure samples between an adaptive run's steps, so curves stay smooth at pixel resolution.
#pragma once
#include <span>

#include "core/trajectory.hpp"

namespace vibra::scenes {

/// The spacing in time at which a figure `width` pixels wide over [0, T]
/// samples an adaptive run between its steps (two a pixel column), or 0 for
/// a fixed-step run, whose rows a figure draws as they are.
inline double inside_step_spacing(const TimeMesh& mesh, int width) {
  return mesh.adaptive() ? mesh.T / (2.0 * width) : 0;
}

/// Calls each(row) for rows at from + k spacing strictly inside the run's
/// last step (from its dense output), so that a curve follows the solution
/// between an adaptive run's long, uneven steps instead of a chord.
template <class Each>
void rows_inside_step(const Trajectory& run, double from, double spacing, std::span<double> row, Each&& each) {
  if (!(spacing > 0)) return;
  for (double t = from + spacing; t < run.t(); t += spacing) {
    run.row_at(t, row);
    each(std::span<const double>(row));
  }
}

}  // namespace vibra::scenes
