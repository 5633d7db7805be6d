// The pendulum's free-body diagram: support, wire, bob, forces and the angle.
#pragma once
#include "scenes/diagrams/diagram.hpp"
#include "scenes/diagrams/forces/force_scale.hpp"
#include "scenes/diagrams/pendulum/pendulum_geometry.hpp"
#include "scenes/diagrams/pendulum/pendulum_support.hpp"
#include "scenes/config/scene_style.hpp"

namespace vibra::scenes {

/// The pendulum's free-body diagram (docs/drawing.md): ceiling (or a bearing
/// block, when the pendulum swings up past it) and pivot,
/// wire, bob, the dashed vertical, the angle arc, and the arrows mg, S and
/// the magnified drag D. Rows are the pendulum models': t, theta, omega, S, D.
/// Panels: theta (degrees), S and D against time.
class PendulumDiagram final : public Diagram {
 public:
  /// The room around the bob's path for the arrows, in units of L: the
  /// longest arrow; longer forces are drawn clipped with a break mark.
  static constexpr double kArrowRoom = 0.5;
  /// The room of S > 0, toward the pivot: most of the wire.
  static constexpr double kInwardRoom = 0.85;

  PendulumDiagram(PendulumDiagramOptions, SceneColors);

  void record(std::span<const double> row, WorldBox& world) override;
  void finish_recording(WorldBox& world) override;
  void draw_static(render::Canvas&, const render::WorldView&) const override;
  void draw(render::Canvas&, const render::WorldView&, std::span<const double> row) override;
  std::vector<PanelSpec> panels() const override;
  std::optional<ForceKey> force_key() const override;
  const PendulumSupport& support() const { return support_; }
  const ForceScale& force_scale() const { return scale_; }
  /// Whether the link is drawn and named as a strut (some S < 0 in the run).
  bool strut() const { return pushed_; }

 private:
  /// The wire, or the strut when the run pushes the bob (S < 0).
  void draw_link(render::Canvas&, const render::WorldView&, const PendulumGeometry&) const;
  /// `--annotate geometry`: the unit vectors, the pivot (x0, y0) and L.
  void draw_geometry(render::Canvas&, const render::WorldView&, const PendulumGeometry&,
                     const Point& away_from_vertical) const;

  /// A ceiling, or a bearing block when the bob rises near the pivot's height.
  PendulumSupport support_{Point::Zero()};
  /// Whether the run has any drag at all (alpha > 0): no D arrow otherwise.
  bool has_drag_ = false;
  /// Whether S < 0 anywhere in the run: the link pushes the bob (over the
  /// top), a rod in compression, a strut, not a wire.
  bool pushed_ = false;
  ForceScale scale_;
  PendulumDiagramOptions options_;
  SceneColors colors_;
};

}  // namespace vibra::scenes
