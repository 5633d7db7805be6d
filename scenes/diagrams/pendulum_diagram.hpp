#pragma once
#include "scenes/diagrams/diagram.hpp"
#include "scenes/diagrams/pendulum_geometry.hpp"
#include "scenes/scene_style.hpp"

namespace vibra::scenes {

/// The pendulum's free-body diagram (docs/drawing.md): ceiling and pivot,
/// wire, bob, the dashed vertical, the angle arc, and the arrows mg, S and
/// the magnified drag D. Rows are the pendulum models': t, theta, omega, S, D.
/// Panels: theta (degrees), S and D against time.
class PendulumDiagram final : public Diagram {
 public:
  PendulumDiagram(PendulumDiagramOptions, SceneColors);

  void record(std::span<const double> row, WorldBox& world) override;
  void finish_recording(WorldBox& world) override;
  void draw_static(render::Canvas&, const render::WorldView&) const override;
  void draw(render::Canvas&, const render::WorldView&, std::span<const double> row) override;
  std::vector<PanelSpec> panels() const override;

 private:
  PendulumDiagramOptions options_;
  SceneColors colors_;
};

}  // namespace vibra::scenes
