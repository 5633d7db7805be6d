// SystemScene: a system's diagram alone or beside stacked panels, the scene of every model.
#pragma once
#include <memory>
#include <optional>
#include <vector>

#include "core/trajectory.hpp"
#include "render/draw/caption.hpp"
#include "render/labels/drawing_record.hpp"
#include "render/labels/label_placer.hpp"
#include "scenes/diagrams/diagram.hpp"
#include "scenes/overlays/frame_heading.hpp"
#include "scenes/overlays/note_callouts.hpp"
#include "scenes/panels/energy_bars.hpp"
#include "scenes/panels/quantity_panels.hpp"
#include "scenes/panels/scene_panel.hpp"
#include "scenes/overlays/run_legend.hpp"
#include "scenes/scene.hpp"
#include "scenes/config/scene_style.hpp"
#include "scenes/static_layer.hpp"

namespace vibra::scenes {

/// A system's diagram alone (layout fbd) or beside stacked panels (fbd+plot:
/// the diagram's own quantities against time with a cursor at the current
/// time, or the panels chosen), with the time read-out, the caption and,
/// when asked, energy bars at the diagram's side. The view is fixed over the run
/// from the pre-pass, so nothing jumps and nothing is clipped, unless the
/// diagram follows its body (a vehicle on a long road). A comparison's
/// diagram brings a legend of its runs, which gets a column of its own.
class SystemScene final : public Scene {
 public:
  /// `panels` empty: the diagram's own. `bars` null: none.
  SystemScene(int width, int height, const TrajectoryInfo&, SceneStyle, std::unique_ptr<Diagram>,
              std::vector<QuantityPanelSpec> panels = {}, std::unique_ptr<EnergyBars> bars = nullptr);

  void record(std::span<const double> row) override;
  void observe(std::span<const double> row) override;
  void record_between(std::span<const double> row) override;
  void observe_between(std::span<const double> row) override;
  void look_ahead(std::span<const std::vector<double>> next_samples) override;
  double sample_interval() const override;
  void draw(render::Canvas&, std::span<const double> row) override;
  void skip(const render::Canvas&, std::span<const double> row) override;
  const render::DrawingRecord* last_layout() const override { return &last_frame_; }
  void set_label_chain(long long chain) override {
    if (chain != label_chain_) label_memory_.clear(), label_chain_ = chain;
  }

  /// The diagram's world box over the run (after record()).
  const WorldBox& world_box() const { return world_; }
  /// The view the diagram is drawn through at this row (after record()).
  render::WorldView view_at(std::span<const double> row);
  /// The caption as fitted to the diagram's width (after record()); none without one.
  const std::optional<render::Caption>& caption() {
    prepare();
    return caption_;
  }
  /// Where the diagram, its caption and read-out are drawn.
  const render::PixelRect& diagram_area() const { return diagram_area_; }
  /// Panel i beside the diagram, top to bottom.
  const ScenePanel& panel(size_t i) const { return *panels_.at(i); }
  /// The title and equation across the top.
  const FrameHeading& heading() const { return heading_; }
  /// Where its labels may go: the drawing area short of the energy bars (after a frame is drawn).
  render::PixelRect label_area(double scale) const;
  /// The energy bars' area, if it has bars (after a frame is drawn).
  std::optional<render::PixelRect> bars_area() const {
    return bars_ ? std::optional<render::PixelRect>(bars_->area()) : std::nullopt;
  }

 private:
  void prepare();
  void draw_static(render::Canvas&);
  /// The view through `moving` when the diagram follows its body, else the fixed one.
  render::WorldView view_for(const std::optional<FollowingView>& moving) const;
  /// The curves drawn so far, for the layer under frame time t.
  StaticLayer::Grow progress_to(std::span<const double> row);

  int height_;
  SceneStyle style_;
  FrameHeading heading_;
  std::unique_ptr<Diagram> diagram_;
  /// Where the diagram may draw: its area without the legend's column.
  render::PixelRect drawing_area() const;
  /// The legend column's top right corner.
  render::Point legend_corner(double scale) const;
  /// How wide the force key may be: the diagram's part, short of the energy bars.
  double key_width(double scale) const;
  /// Beside the drawing, or above it when that draws the diagram larger (prepare()).
  void place_legend();

  render::PixelRect diagram_area_, view_area_;
  /// The comparison's legend sits above the drawing instead of in a column
  /// beside it, when that draws the diagram larger (a wide drawing).
  bool legend_on_top_ = false;
  bool key_note_row_ = false;  ///< the force key's note on a row of its own (decided with the layout)
  RunLegend legend_;
  std::vector<std::unique_ptr<ScenePanel>> panels_;
  size_t time_labels_panel_ = 0;  ///< the lowest panel against time labels the time axis
  std::unique_ptr<EnergyBars> bars_;
  std::optional<NoteCallouts> notes_;
  WorldBox world_;
  std::optional<render::WorldView> view_;
  std::optional<render::Caption> caption_;  ///< set with the view
  StaticLayer background_;
  /// What the parts drawn once (ground, walls, legend, caption) cover.
  render::Outline static_outline_;
  /// The last frame's diagram part: its outline and labels.
  render::DrawingRecord last_frame_;
  render::LabelMemory label_memory_;  ///< where the labels of the last frame drawn went
  render::StaticMarks static_marks_;  ///< static_outline_ marked into the label placer's grid
  long long label_chain_ = -1;
};

}  // namespace vibra::scenes
