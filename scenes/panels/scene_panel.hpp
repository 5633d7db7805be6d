// ScenePanel: one panel beside a diagram, curves against time or the phase plane.
#pragma once
#include <span>
#include <vector>

#include "render/draw/canvas.hpp"
#include "render/plot/plot_panel.hpp"
#include "scenes/static_layer.hpp"

namespace vibra::scenes {

/// One panel beside a diagram (layout fbd+plot), whatever it plots: curves
/// against time (SeriesPanel) or the phase plane (PhasePanel). SystemScene
/// feeds every panel the same solution rows (t first, then the model's
/// columns) in the order a Scene gets them.
class ScenePanel {
 public:
  virtual ~ScenePanel() = default;
  /// Pre-pass over every solver row of the run: fixed ranges (and, for a
  /// whole-run plot, its curves).
  virtual void record(std::span<const double> row) = 0;
  /// Live, for every solver step up to the frame being drawn.
  virtual void observe(std::span<const double> row) = 0;
  /// Rows between solver steps (an adaptive run's dense output, a step cut
  /// by an impact): curves pass through them, but they are no mesh points.
  virtual void record_between(std::span<const double> row) { record(row); }
  virtual void observe_between(std::span<const double> row) { observe(row); }
  /// Each straight run's next sample (Scene::look_ahead).
  virtual void look_ahead(std::span<const std::vector<double>> next_samples) { (void)next_samples; }
  /// Simulated time per pixel column of its curves; 0 when not against time.
  virtual double time_per_column() const { return 0; }
  /// After the pre-pass: fixes the ranges.
  virtual void finish_recording() = 0;
  /// Whether the horizontal axis is time (shared by the stacked time panels:
  /// only the lowest labels it).
  virtual bool against_time() const { return true; }
  /// The axes and mapping of a panel against time as last drawn (a note's
  /// arrow points into it); null for others.
  virtual const render::PlotPanel* time_plot() const { return nullptr; }
  /// What never changes per frame, drawn once under every frame.
  virtual void draw_static(render::Canvas&, bool time_labels) const = 0;
  /// Extends what the layer under the frames keeps up to the time of `row`,
  /// the solution then (from t = 0 when the layer is new); nothing for a
  /// panel without such a layer.
  virtual void draw_progress(LayerGrowth& growth, std::span<const double> row) { (void)growth, (void)row; }
  /// The dynamic part at time t; `row` is the solution at t.
  virtual void draw(render::Canvas&, double t, std::span<const double> row, bool time_labels) const = 0;
};

}  // namespace vibra::scenes
