#pragma once
#include <memory>
#include <optional>
#include <vector>

#include "scenes/diagram.hpp"
#include "scenes/run_legend.hpp"
#include "scenes/scene.hpp"
#include "scenes/scene_style.hpp"
#include "scenes/series_panel.hpp"
#include "scenes/static_layer.hpp"

namespace vibra::scenes {

/// A system's diagram alone (layout fbd) or beside stacked panels of its own
/// quantities against time with a cursor at the current time (fbd+plot),
/// with the time read-out and the caption. The view is fixed over the run
/// from the pre-pass, so nothing jumps and nothing is clipped, unless the
/// diagram follows its body (a vehicle on a long road). A comparison's
/// diagram brings a legend of its runs, which gets a column of its own.
class SystemScene final : public Scene {
 public:
  SystemScene(int width, int height, double t_end, SceneStyle, std::unique_ptr<Diagram>);

  void record(std::span<const double> row) override;
  void observe(std::span<const double> row) override;
  void draw(render::Canvas&, std::span<const double> row) override;
  void skip(const render::Canvas&, std::span<const double> row) override;

  /// The diagram's world box over the run (after record()).
  const WorldBox& world_box() const { return world_; }
  /// The view the diagram is drawn through at this row (after record()).
  render::WorldView view_at(std::span<const double> row);

 private:
  void prepare();
  void draw_static(render::Canvas&);
  /// The curves drawn so far, for the layer under frame time t.
  StaticLayer::Grow progress_to(double t);

  int height_;
  SceneStyle style_;
  std::unique_ptr<Diagram> diagram_;
  /// Where the diagram may draw: its area without the legend's column.
  render::PixelRect drawing_area() const;
  /// The legend column's top right corner.
  render::Point legend_corner(double scale) const;

  render::PixelRect diagram_area_, view_area_;
  RunLegend legend_;
  std::vector<SeriesPanel> panels_;
  WorldBox world_;
  std::optional<render::WorldView> view_;
  StaticLayer background_;
};

}  // namespace vibra::scenes
