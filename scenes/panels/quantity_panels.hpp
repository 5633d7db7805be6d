// The panels `vibra render --panels` can put beside a diagram: any of the model's columns against t, and `phase`, `energy`, `error`, `period`.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "core/trajectory.hpp"
#include "render/draw/color.hpp"
#include "scenes/panels/phase_panel.hpp"
#include "scenes/panels/scene_panel.hpp"
#include "scenes/panels/series_panel.hpp"

namespace vibra::scenes {

/// A panel to draw: against time (`curves` and `references`) or the phase
/// plane (`phase` non-empty). Every curve is a function of one row of the
/// run's columns (t first), so a comparison builds one set of `curves` (or
/// `phase`) per member by feeding each member's own row; `references` (the
/// exact solution, the exact period) are the same for every member.
struct QuantityPanelSpec {
  std::string label;  ///< the y label (Pango markup)
  std::vector<SeriesSpec> curves;
  std::vector<SeriesSpec> references;
  std::string x_label;  ///< phase only
  std::vector<PhaseCurveSpec> phase;
  /// Phase only: both axes at one scale (u against v/w, so that an undamped
  /// oscillator's orbit is drawn as the circle it is).
  bool equal_scales = false;
  double least_span = 0;  ///< the y range spans at least this much (SeriesPanel::set_least_span)
  std::string empty_note;  ///< shown when the first curve has no value in the run
  bool is_phase() const { return !phase.empty(); }
};

/// The names `--panels` accepts for a run: its columns but t, then phase,
/// energy, error and period.
std::vector<std::string> render_panel_names(const TrajectoryInfo&);

/// The panel `name` for a run, its curves in `color` (labelled
/// `curve_label`, "" for none) and the references in `reference_color`.
/// Stateful curves (energy's E(0), period's crossings) are made here, one per
/// call: call once per member. Throws UsageError for an unknown name (with
/// the closest), and for `error` without an exact solution or `energy`
/// without a mechanical energy (naming the fix).
QuantityPanelSpec quantity_panel(const std::string& name, const TrajectoryInfo&, render::Color color,
                                 const std::string& curve_label, render::Color reference_color);

/// The drawn panel of a spec in `outer`: a PhasePanel (its trail one period
/// long, or T/8 without a period) or a SeriesPanel (curves, then references).
std::unique_ptr<ScenePanel> make_scene_panel(QuantityPanelSpec, const TrajectoryInfo&, const render::PixelRect& outer,
                                             double scale, WindowMode, double window);

}  // namespace vibra::scenes
