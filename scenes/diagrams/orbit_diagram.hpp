// The two-body orbit's diagram (section 1.12.10): star, planet and trail.
#pragma once
#include <array>
#include <cmath>

#include "render/draw/polyline/trail.hpp"
#include "scenes/diagrams/diagram.hpp"
#include "scenes/diagrams/forces/force_scale.hpp"
#include "scenes/config/scene_style.hpp"

namespace vibra::scenes {

/// The planet's orbit of section 1.12.10 for the `two-body` model (scaled,
/// star at rest at the origin): the star, the planet, its trail (the whole
/// run, or the last `window` time units with --window, fading), the exact
/// circle dashed when the start is on a circular orbit, and arrows for the
/// gravity -x/|x|^3 (to one scale) and the velocity (to its own).
/// Panels: x, y and r - r(0). Rows: t, x, y, vx, vy.
class OrbitDiagram final : public Diagram {
 public:
  /// `window`: time units of trail to show; 0 for the whole run.
  OrbitDiagram(double window, double t_end, SceneColors);

  void record(std::span<const double> row, WorldBox& world) override;
  void record_other(std::span<const double> row, WorldBox&) override;
  void finish_recording(WorldBox& world) override;
  void draw_static(render::Canvas&, const render::WorldView&) const override;
  void draw(render::Canvas&, const render::WorldView&, std::span<const double> row) override;
  std::vector<PanelSpec> panels() const override;

  /// Gravity and velocity at a row, world units.
  std::array<Arrow, 2> arrows(std::span<const double> row) const;
  const render::Trail& trail() const { return trail_; }
  /// Time units of trail drawn (0: the whole run).
  double window() const { return window_; }
  /// Radius of the exact circular orbit, 0 when the start is not circular.
  double circle_radius() const { return circle_radius_; }

 private:
  double window_, t_end_;
  SceneColors colors_;
  ForceScale gravity_, speed_;
  render::Trail trail_{1e-3};
  WorldBox bodies_;
  double circle_radius_ = 0;
  double start_radius_ = 0;  ///< |x| at the first row, for the panel r - r(0)
  bool first_ = true;
};

}  // namespace vibra::scenes
