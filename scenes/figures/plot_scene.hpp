// PlotScene: moving plots without a diagram (layouts plot and grid), stacked on one time axis.
#pragma once
#include <string>
#include <vector>

#include "scenes/diagrams/diagram.hpp"
#include "scenes/overlays/frame_heading.hpp"
#include "scenes/overlays/note_callouts.hpp"
#include "scenes/panels/series_panel.hpp"
#include "scenes/overlays/run_legend.hpp"
#include "scenes/scene.hpp"
#include "scenes/config/scene_style.hpp"
#include "scenes/static_layer.hpp"

namespace vibra::scenes {

/// Moving plots without a diagram, stacked on one time axis: any model's
/// main quantity with its exact solution dashed (layout plot), a
/// comparison's members in one panel, or one panel per member (layout grid,
/// the chapter's linked panels for long runs). A legend of runs, when given,
/// gets a column of its own at the right.
class PlotScene final : public Scene {
 public:
  /// Panels over the run's [0, T] (`info`), marking its mesh points where they are far apart.
  PlotScene(int width, int height, const TrajectoryInfo& info, SceneStyle, std::vector<PanelSpec>,
            std::vector<LegendEntry> = {});

  void record(std::span<const double> row) override;
  void observe(std::span<const double> row) override;
  void record_between(std::span<const double> row) override;
  void observe_between(std::span<const double> row) override;
  void look_ahead(std::span<const std::vector<double>> next_samples) override;
  double sample_interval() const override;
  void draw(render::Canvas&, std::span<const double> row) override;
  void skip(const render::Canvas&, std::span<const double> row) override;
  /// The title and equation band over the panels (empty without them).
  const FrameHeading& heading() const { return heading_; }

 private:
  void prepare();
  void draw_static(render::Canvas&);
  StaticLayer::Grow progress_to(std::span<const double> row);

  SceneStyle style_;
  FrameHeading heading_;
  render::PixelRect area_;
  RunLegend legend_;
  std::vector<SeriesPanel> panels_;
  StaticLayer background_;
  std::optional<NoteCallouts> notes_;
  bool prepared_ = false;
};

/// The panel of layout plot: the main quantity, numerical and exact (dashed, where known).
PanelSpec main_quantity_panel(const SceneStyle&, const std::string& quantity, std::function<double(double)> exact,
                              const std::string& exact_label);

}  // namespace vibra::scenes
