// The figure vibra plot --compare draws without --panels: paths or curves against t and the phase plane.
#pragma once
#include <string>
#include <vector>

#include "core/comparison.hpp"
#include "render/plot/figure.hpp"

namespace vibra::scenes {

/// What `vibra plot --compare` draws without --panels: the path for models
/// with x and y, else the main quantity against t and the phase plane.
std::vector<std::string> default_comparison_panels(const TrajectoryInfo&);

/// Runs a comparison to its end into a figure: every panel (the names of
/// plot_panel_names) draws one curve per member in its own colour, plus the
/// exact solution dashed where known; one legend, on the first panel, names
/// the members. A member that leaves the view (twice the largest amplitude the
/// models can reach, when they know it) or turns non-finite is drawn up to
/// there, marked with a dot, and its legend entry says when it blew up.
render::Figure comparison_figure(Comparison&, const std::vector<std::string>& panels, int width, int height,
                                 const std::string& title);

}  // namespace vibra::scenes
