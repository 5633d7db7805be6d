// The figure of vibra plot: a trajectory streamed once into the named panels, stacked.
#pragma once
#include <string>
#include <vector>

#include "core/trajectory.hpp"
#include "render/plot/figure.hpp"
#include "scenes/panels/plot_panels.hpp"

namespace vibra::scenes {

/// Streams the trajectory once into a figure of the named panels, stacked
/// (time panels next to each other share the t axis). Throws UsageError for
/// an unknown panel, `exact` without an exact solution, or an endless run.
/// `mark_mesh`: a dot at every step on the time panels (--annotate mesh, MeshMarks).
render::Figure trajectory_figure(Trajectory&, const std::vector<std::string>& panels, int width, int height,
                                 const std::string& title, bool mark_mesh = false);

}  // namespace vibra::scenes
