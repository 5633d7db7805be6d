// The washing machine's diagram (section 1.12.4): a body on springs and a damper, shaken by its drum.
#pragma once
#include <optional>

#include "scenes/diagrams/diagram.hpp"
#include "scenes/diagrams/forces/force_scale.hpp"
#include "scenes/config/scene_style.hpp"

namespace vibra::scenes {

/// The washing machine of section 1.12.4 for the `resonance` model
/// u'' + beta u' + u = sin(gamma t): a machine body on two springs and a
/// damper over the floor, moving vertically, its drum turning at gamma with
/// an off-centre mass at the forcing's phase gamma t (the mass is highest
/// when the forcing pushes up hardest). Arrows on the body: the springs' -u,
/// the damper's -beta u' and the drum's sin(gamma t), to one scale per run
/// (ForceScale: the drum's force always reads, longer arrows are clipped with
/// a break mark), each named. Lengths in static deflections (the scaled u),
/// the motion drawn divided by a round number when it dwarfs the body. Panels: u with the steady
/// amplitude, and the forcing.
class WashingMachineDiagram final : public Diagram {
 public:
  WashingMachineDiagram(double beta, double gamma, std::function<double(double)> exact, SceneColors);

  void record(std::span<const double> row, WorldBox& world) override;
  void finish_recording(WorldBox& world) override;
  void draw_static(render::Canvas&, const render::WorldView&) const override;
  void draw(render::Canvas&, const render::WorldView&, std::span<const double> row) override;
  std::vector<PanelSpec> panels() const override;
  std::optional<ForceKey> force_key() const override;

  /// Where the off-centre mass is at time t, relative to the drum's centre.
  Point drum_mass_offset(double t) const;
  /// Springs, damper (beta > 0), drum force, in that order, at a row.
  std::vector<Arrow> force_arrows(std::span<const double> row) const;
  /// Where the body's bottom is drawn at displacement u (drawn ÷ motion_divisor()).
  double body_bottom(double u) const { return leg_ + u / divisor_; }
  /// The motion is drawn divided by this (1: true size), set after the pre-pass.
  double motion_divisor() const { return divisor_; }
  const ForceScale& force_scale() const { return scale_; }

 private:
  Point body_center(double u) const { return {0, body_bottom(u) + 0.5 * height_}; }

  double beta_, gamma_;
  std::function<double(double)> exact_;
  SceneColors colors_;
  double largest_u_ = 0;
  ForceScale scale_;
  double width_ = 4, height_ = 3, leg_ = 3, drum_ = 1.05;
  double divisor_ = 1;
};

}  // namespace vibra::scenes
