#pragma once
#include <memory>
#include <optional>
#include <vector>

#include "render/caption.hpp"
#include "scenes/diagram.hpp"
#include "scenes/scene.hpp"
#include "scenes/scene_style.hpp"
#include "scenes/series_panel.hpp"
#include "scenes/static_layer.hpp"

namespace vibra::scenes {

/// A system's diagram alone (layout fbd) or beside stacked panels of its own
/// quantities against time with a cursor at the current time (fbd+plot),
/// with the time read-out and the caption. The view is fixed over the run
/// from the pre-pass, so nothing jumps and nothing is clipped, unless the
/// diagram follows its body (a vehicle on a long road).
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
  /// The caption as fitted to the diagram's width (after record()); none without one.
  const std::optional<render::Caption>& caption() {
    prepare();
    return caption_;
  }
  /// Where the diagram, its caption and read-out are drawn.
  const render::PixelRect& diagram_area() const { return diagram_area_; }

 private:
  void prepare();
  void draw_static(render::Canvas&);
  /// The curves drawn so far, for the layer under frame time t.
  StaticLayer::Grow progress_to(double t);

  int height_;
  SceneStyle style_;
  std::unique_ptr<Diagram> diagram_;
  render::PixelRect diagram_area_, view_area_;
  std::vector<SeriesPanel> panels_;
  WorldBox world_;
  std::optional<render::WorldView> view_;
  std::optional<render::Caption> caption_;  ///< set with the view
  StaticLayer background_;
};

}  // namespace vibra::scenes
