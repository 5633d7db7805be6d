// The elastic pendulum's diagram (section 1.12.7): pivot, spring wire, bob and forces.
#pragma once
#include <array>
#include <cmath>

#include "render/draw/polyline/trail.hpp"
#include "scenes/diagrams/diagram.hpp"
#include "scenes/diagrams/forces/force_scale.hpp"
#include "scenes/diagrams/pendulum/pendulum_support.hpp"
#include "scenes/config/scene_style.hpp"

namespace vibra::scenes {

/// The elastic pendulum of section 1.12.7 for the `elastic-pendulum` model,
/// in its scaled coordinates (pivot at (0, 1), equilibrium at the origin):
/// the ceiling and pivot, the wire as a spring whose coils stretch with L,
/// the bob, its path over the last two periods fading behind it, and arrows
/// in units of mg to one scale: gravity 1, the wire's force (L - beta)/(1 -
/// beta) toward the pivot, and the drag (gamma/beta^2) |v| v against v.
/// Panels: theta (degrees) and the wire's force. Rows: t, x, y, vx, vy, theta.
class ElasticPendulumDiagram final : public Diagram {
 public:
  ElasticPendulumDiagram(double beta, double gamma, SceneColors);

  void record(std::span<const double> row, WorldBox& world) override;
  void record_other(std::span<const double> row, WorldBox&) override;
  void finish_recording(WorldBox& world) override;
  void draw_static(render::Canvas&, const render::WorldView&) const override;
  void draw(render::Canvas&, const render::WorldView&, std::span<const double> row) override;
  std::vector<PanelSpec> panels() const override;
  std::optional<ForceKey> force_key() const override;

  /// Gravity, the wire's force and the drag at a row, world units.
  std::array<Arrow, 3> force_arrows(std::span<const double> row) const;
  /// The wire's force in units of mg, toward the pivot (negative: compressed).
  double wire_force(std::span<const double> row) const;
  const ForceScale& force_scale() const { return scale_; }
  const PendulumSupport& support() const { return support_; }
  const render::Trail& trail() const { return trail_; }
  static constexpr double kBob = 0.06;       ///< the bob's radius, scaled
  static constexpr double kFade = 4 * M_PI;  ///< the trail shows two periods P = 2 pi

 private:
  double beta_, gamma_;
  SceneColors colors_;
  ForceScale scale_;
  render::Trail trail_{1e-3};
  WorldBox bodies_;
  PendulumSupport support_{Point(0, 1)};
};

}  // namespace vibra::scenes
