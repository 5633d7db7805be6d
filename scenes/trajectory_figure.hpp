#pragma once
#include <string>
#include <vector>

#include "core/trajectory.hpp"
#include "render/figure.hpp"

namespace vibra::scenes {

/// The panels `vibra plot` can draw for a run: every column but t (against
/// t), `exact` (the exact solution over the main quantity's panel), `phase`
/// (the main quantity against its velocity) and, for models with x and y
/// columns, `path` (y against x, equal aspect).
std::vector<std::string> plot_panel_names(const TrajectoryInfo&);

/// What `vibra plot` draws without --panels: the path for models with x and
/// y, theta, S and D for the pendulums (Exercise 1.25), else the main quantity.
std::vector<std::string> default_plot_panels(const TrajectoryInfo&);

/// Checks `panels` against the run and returns them in drawing order, with
/// `exact` folded into the main quantity's panel (or standing in for it).
/// Throws UsageError for an unknown panel (suggesting the nearest), an empty
/// list, `exact` without an exact solution, or an endless run.
std::vector<std::string> ordered_plot_panels(const TrajectoryInfo&, const std::vector<std::string>& panels);

/// The colour of the k-th time panel (vermillion is kept for exact solutions).
render::Color time_panel_color(int k);

/// Streams the trajectory once into a figure of the named panels, stacked
/// (time panels next to each other share the t axis). Throws UsageError for
/// an unknown panel, `exact` without an exact solution, or an endless run.
render::Figure trajectory_figure(Trajectory&, const std::vector<std::string>& panels, int width, int height,
                                 const std::string& title);

}  // namespace vibra::scenes
