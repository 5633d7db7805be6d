#pragma once
#include <string>
#include <vector>

#include "core/trajectory.hpp"

namespace vibra::scenes {

// What `vibra plot` can draw for a model, shared by the figure of one run and
// that of a comparison.

/// Index of the column `name`, or -1.
int column_index(const TrajectoryInfo&, const std::string& name);

/// A column's name as the reader knows it: Greek letters, italics, subscripts (Pango markup).
std::string quantity_markup(const std::string& column);

/// The panels `vibra plot` can draw for a run: every column but t (against
/// t), `exact` (the exact solution over the main quantity's panel), `phase`
/// (the main quantity against its velocity) and, for models with x and y
/// columns, `path` (y against x, equal aspect).
std::vector<std::string> plot_panel_names(const TrajectoryInfo&);

/// What `vibra plot` draws without --panels: the path for models with x and
/// y, theta, S and D for the pendulums (Exercise 1.25), else the main quantity.
std::vector<std::string> default_plot_panels(const TrajectoryInfo&);

/// The panels to draw, top to bottom: `exact` joins the main quantity's panel
/// (or stands in for it when that is not listed). Throws UsageError for an
/// unknown panel (naming the closest) or an empty list.
std::vector<std::string> panel_order(const TrajectoryInfo&, const std::vector<std::string>& panels);

}  // namespace vibra::scenes
