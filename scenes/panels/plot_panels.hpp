// What `vibra plot` can draw for a model, shared by the figure of one run and that of a comparison.
#pragma once
#include <string>
#include <vector>

#include "core/trajectory.hpp"
#include "render/draw/color.hpp"

namespace vibra::scenes {

/// Index of the column `name`, or -1.
int column_index(const TrajectoryInfo&, const std::string& name);

/// How a column is read on screen, in panels, figures and pages alike:
/// angles in degrees (θ, marked °); every other column as computed. CSV
/// keeps the computed values (radians).
double display_factor(const std::string& column);

/// A column's name as the reader knows it: Greek letters, italics, subscripts (Pango markup).
std::string quantity_markup(const std::string& column);
/// A column's symbol alone, in italics: "<i>θ</i>", "<i>u</i>".
std::string quantity_symbol(const std::string& column);

/// The phase plane's vertical axis for a run. Where the model has a
/// small-oscillation period P, the velocity over w = 2 pi / P in the main
/// quantity's own unit, drawn at one scale with it: an undamped oscillator's
/// exact orbit u^2 + (v/w)^2 = U^2 is then the circle it is (the pendulum's
/// w0 = sqrt(g/L), labelled θ′/ω₀). Without a period, the velocity column as it is.
struct PhaseVelocityAxis {
  int column;            ///< the velocity column (velocity_column)
  double factor;         ///< what the column is multiplied by on screen
  std::string label;     ///< Pango markup
  bool equal_scales;     ///< draw both axes at one scale
};
PhaseVelocityAxis phase_velocity_axis(const TrajectoryInfo&);

/// The panels `vibra plot` can draw for a run: every column but t (against
/// t), `exact` (the exact solution over the main quantity's panel), `phase`
/// (the main quantity against its velocity) and, for models with x and y
/// columns, `path` (y against x, equal aspect); for the sliding box,
/// `friction` (its spring force and friction against u).
std::vector<std::string> plot_panel_names(const TrajectoryInfo&);

/// What `vibra plot` draws without --panels: the path for models with x and
/// y, theta, S and D for the pendulums (Exercise 1.25), else the main quantity.
std::vector<std::string> default_plot_panels(const TrajectoryInfo&);

/// The panels to draw, top to bottom: `exact` joins the main quantity's panel
/// (or stands in for it when that is not listed). Throws UsageError for an
/// unknown panel (naming the closest) or an empty list.
std::vector<std::string> panel_order(const TrajectoryInfo&, const std::vector<std::string>& panels);

/// Throws the UsageError for a panel name not in `valid`: the closest valid
/// name and the whole list.
[[noreturn]] void reject_unknown_panel(const std::string& name, const std::vector<std::string>& valid);

/// Which runs have an exact solution, for the message that a panel needs one.
extern const char* const kRunsWithExactSolution;

/// panel_order, after checking that the run can be plotted: `exact` needs an
/// exact solution, and a plot needs a finite end time (UsageError otherwise).
std::vector<std::string> ordered_plot_panels(const TrajectoryInfo&, const std::vector<std::string>& panels);

/// The colour of the k-th time panel (vermillion is kept for exact solutions).
render::Color time_panel_color(int k);

}  // namespace vibra::scenes
