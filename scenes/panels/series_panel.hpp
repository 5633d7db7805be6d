// SeriesPanel: curves against time beside a diagram, following a long run (full or moving window).
#pragma once
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "render/draw/polyline/growing_polyline.hpp"
#include "render/plot/column_envelope.hpp"
#include "render/plot/plot_panel.hpp"
#include "render/plot/rolling_envelope.hpp"
#include "scenes/panels/sample_bracket.hpp"
#include "scenes/panels/scene_panel.hpp"

namespace vibra::scenes {

/// How a plot follows a long run (docs/drawing.md). `whole_run` shows [0, T] with
/// the curve drawn up to the current time; the others show a window of width w.
enum class WindowMode {
  whole_run,
  drawing,   ///< draw from the window's start; at each multiple of w jump one width ahead
  movement,  ///< once t > w the window slides with t
  jumps,     ///< show the last complete window; change only when a window completes
};

/// Parses "drawing", "movement", "jumps"; throws UsageError otherwise.
WindowMode parse_window_mode(const std::string&);

/// One curve of a panel: a value computed from a solution row (t first).
struct SeriesSpec {
  std::string label;  ///< legend text (Pango markup); "" = no legend entry
  render::Color color;
  std::function<double(std::span<const double> row)> value;
  bool dashed = false;
  /// A known function of t (the exact solution): drawn by evaluating it at
  /// every half pixel column, smooth at any dt, instead of joining its values
  /// at the solver's steps.
  std::function<double(double t)> of_time = nullptr;
  /// Whether each value comes from its row alone (a column, its energy or
  /// error), so that the curve's points are the mesh's: marked where the mesh
  /// points are far apart. False for running measures (a period).
  bool mesh_values = true;
};

/// A plot panel of one or more curves against time, fed a solution row at a
/// time. A curve's value may be NaN where it has none (a period not yet
/// measured): nothing is drawn there. Memory is one envelope cell per pixel column, whatever the run:
/// whole_run keeps one envelope over [0, T] (filled by record() in a
/// pre-pass); window modes keep the newest two windows (filled by observe()).
class SeriesPanel final : public ScenePanel {
 public:
  SeriesPanel(const render::PixelRect& outer, double scale, std::string y_label, std::vector<SeriesSpec> series,
              double t_end, WindowMode mode, double window);

  /// Pre-pass over the whole run: the y range (fixed for every frame) and, for
  /// whole_run, the curves.
  void record(std::span<const double> row) override;
  /// Live, for every solver step up to the frame being drawn (window modes).
  void observe(std::span<const double> row) override;
  /// Rows between steps: on the curves, but not marked as mesh points.
  void record_between(std::span<const double> row) override;
  void observe_between(std::span<const double> row) override;
  void look_ahead(std::span<const std::vector<double>> next_samples) override;
  /// Fixes the y range after the pre-pass.
  void finish_recording() override;
  double time_per_column() const override { return window_ / std::max(1, panel_.columns()); }
  /// The y range spans at least this much about the curves' middle (before
  /// finish_recording), so a nearly flat curve is not blown up to fill it.
  void set_least_span(double span) { least_span_ = span; }
  /// Shown in the panel when the pre-pass found no value of the first curve
  /// (e.g. no period completed), so an empty panel says why.
  void set_empty_note(std::string note) { empty_note_ = std::move(note); }
  /// The rows are the mesh points t_n = n dt of a fixed-step scheme: where
  /// they lie at least kMarkedSpacing pixels apart, a disc marks each on the
  /// curves of mesh values (the book's figures of coarse runs). 0: none.
  void mark_mesh_points(double dt) { mesh_dt_ = dt; }
  /// How far apart (720p pixels) mesh points must be to be marked.
  static constexpr double kMarkedSpacing = 6;

  /// Whether draw_static() holds everything that does not change per frame.
  bool has_static_axes() const { return mode_ == WindowMode::whole_run; }
  /// Axes (whole_run only): nothing of the run, which is drawn as it happens.
  void draw_static(render::Canvas&, bool time_labels) const override;
  /// whole_run: extends the curves drawn on the layer up to time t (from
  /// t = 0 when the layer is new): their samples at or before t, and the
  /// segment on from the last of them to where the curve is at t, never a
  /// sample after t. The layer keeps what is final, so each frame redraws a
  /// strip at the curves' ends, and comes out as the still at t draws them.
  void draw_progress(LayerGrowth& growth, std::span<const double> row) override;
  /// The dynamic part at time t: the cursor, and for window modes the axes
  /// and curves too (they move). `row` is the solution at t.
  void draw(render::Canvas&, double t, std::span<const double> row, bool time_labels) const override;
  /// Series i's value as drawn at the frame's time t, where `row` is the
  /// state then: a value of its row alone on the straight line between its
  /// values at the samples around t (SampleBracket), where its curve runs.
  double value_drawn(size_t i, double t, std::span<const double> row) const;
  /// The radius of series i's mesh-point marks (pixels), 0 for none.
  double marker_radius(size_t i) const;
  /// Series i's mesh points marked so far (time, value): the whole run's
  /// after the pre-pass, or the moving window's recent ones.
  const std::vector<std::pair<double, double>>& marks(size_t i) const { return marks_[i]; }
  /// The panel's axes and mapping as last drawn (for tests and overlays).
  const render::PlotPanel& plot() const { return panel_; }
  const render::PlotPanel* time_plot() const override { return &panel_; }

 private:
  std::pair<double, double> window_at(double t) const;

  void draw_axes(render::Canvas&, bool time_labels) const;
  void draw_cursors(render::Canvas&, double t, std::span<const double> row) const;
  /// Adds row's values to the curves (and, for a mesh row, to the marks).
  void add_row(std::span<const double> row, bool mesh_row);
  void add_recent(std::span<const double> row, bool mesh_row);
  /// Series i's marks up to until_x as discs, clipped to x >= from_x (a whole pixel).
  void draw_marks(render::Canvas&, size_t i, double from_x, double until_x) const;
  /// whole_run: each curve over [0, T] in pixels, made once the ranges are fixed.
  const std::vector<render::GrowingPolyline>& whole_curves() const;

  mutable render::PlotPanel panel_;
  std::string y_label_;
  std::vector<SeriesSpec> series_;
  double t_end_;
  WindowMode mode_;
  double window_;
  std::vector<render::ColumnEnvelope> whole_;
  std::vector<render::RollingEnvelope> recent_;
  double lo_ = 1e300, hi_ = -1e300;
  double least_span_ = 0;
  std::string empty_note_;
  bool first_curve_seen_ = false;
  mutable std::vector<render::GrowingPolyline> whole_curves_;
  double mesh_dt_ = 0;
  std::vector<SampleBracket> brackets_;  ///< per series: its values at the samples around the frame
  std::vector<std::vector<std::pair<double, double>>> marks_;  ///< per series: (t, value) of mesh rows
  /// Series indices in drawing order: the runs' curves, the first (measured)
  /// last of them so that it is on top; then the dashed references (exact
  /// solutions) over them, where their gaps let what is under them show.
  std::vector<size_t> order_;
  double progress_x_ = -1;  ///< whole_run: curves are drawn on the layer up to this pixel x
  double settled_x_ = 0;     ///< whole_run: left of this pixel, the layer's curves are final
};

}  // namespace vibra::scenes
