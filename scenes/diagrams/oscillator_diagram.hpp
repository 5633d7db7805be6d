// The spring-mass system's diagram (Figs 1.17, 1.18): wall, spring, body on wheels, dashpot and forces.
#pragma once
#include <functional>
#include <optional>

#include "core/models/vibration_law.hpp"
#include "scenes/diagrams/diagram.hpp"
#include "scenes/diagrams/forces/drawn_force.hpp"
#include "scenes/diagrams/forces/force_scale.hpp"
#include "scenes/overlays/horizontal_layout.hpp"
#include "scenes/config/scene_style.hpp"

namespace vibra::scenes {

/// The spring-mass system of Figs 1.17 and 1.18 for the `vibration` model: a
/// wall, a spring to a body on wheels over a hatched floor, a dashpot beside
/// the spring when b > 0, the displacement u from equilibrium marked, and
/// arrows on the body for the spring force -s(u), the damper force -f(u')
/// and F(t), all to one scale. Panels: u (with the exact solution where
/// known), v, and the forces when there is more than the spring.
class OscillatorDiagram final : public Diagram {
 public:
  OscillatorDiagram(VibrationLaw, std::function<double(double)> exact, SceneColors);

  void record(std::span<const double> row, WorldBox& world) override;
  void finish_recording(WorldBox& world) override;
  void draw_static(render::Canvas&, const render::WorldView&) const override;
  void draw(render::Canvas&, const render::WorldView&, std::span<const double> row) override;
  std::vector<PanelSpec> panels() const override;
  std::optional<ForceKey> force_key() const override;

  /// The arrows at a row, in world units (after finish_recording): spring,
  /// damper (when b > 0) and external force (when F is given), from the body.
  std::vector<Arrow> force_arrows(std::span<const double> row) const;
  /// The wheels' turn at displacement u, counterclockwise positive: they
  /// roll without slipping, so a body moving right turns them clockwise.
  double wheel_turn(double u) const;
  const HorizontalLayout& layout() const { return *layout_; }
  const ForceScale& force_scale() const { return scale_; }

 private:
  bool has_damper() const { return law_.damping != Damping::none; }
  double spring_height() const;
  double damper_height() const { return layout_->height_at(0.25); }

  VibrationLaw law_;
  std::function<double(double)> exact_;
  SceneColors colors_;
  double largest_u_ = 0, lowest_u_ = 0, highest_u_ = 0;
  /// The largest push to the right over the run of -s(u), -f(u') and F(t).
  double pushes_right_[3] = {0, 0, 0};
  ForceScale scale_;
  std::optional<HorizontalLayout> layout_;
};

}  // namespace vibra::scenes
