// The bouncing ball's diagram (section 1.12.9): ground, ball and its velocity arrow.
#pragma once
#include <functional>
#include <vector>

#include "scenes/diagrams/diagram.hpp"
#include "scenes/diagrams/forces/drawn_force.hpp"
#include "scenes/config/scene_style.hpp"

namespace vibra::scenes {

/// The bouncing ball of section 1.12.9 for the `bouncing-ball` model: the
/// hatched ground, the ball resting on it at height h, its velocity arrow
/// (to one scale over the run, lifted to end on the ground rather than pass
/// through it), the weight mg and, once the ball rests on the ground, the
/// normal force N = mg up from the ground beside it (both one length: the key's
/// unit is mg). An impact lasts no time in the model (section 1.12.9): the
/// ground's impulse reverses v and is drawn as a burst on the ground that
/// fades within a fifth of a period, not as a force; a tally counts them.
/// Panels: h with the exact height dashed, and v, whose jumps at the impacts
/// are vertical.
class BouncingBallDiagram final : public Diagram {
 public:
  BouncingBallDiagram(double g, double period, std::function<double(double)> exact, SceneColors);

  void record(std::span<const double> row, WorldBox& world) override;
  void record_other(std::span<const double> row, WorldBox&) override;
  void finish_recording(WorldBox& world) override;
  void draw_static(render::Canvas&, const render::WorldView&) const override;
  void draw(render::Canvas&, const render::WorldView&, std::span<const double> row) override;
  std::vector<PanelSpec> panels() const override;
  std::optional<ForceKey> force_key() const override;

  /// The velocity arrow (to scale, never below the ground), in world units.
  Arrow velocity_arrow(std::span<const double> row) const;
  /// The forces on the ball at a row: the weight, and the normal force while it rests.
  std::vector<DrawnForce> forces(std::span<const double> row) const;
  /// Resting on the ground: the model holds h = 0, v = 0 from its last impact on.
  static bool at_rest(std::span<const double> row) { return row[1] == 0 && row[2] == 0; }
  Point ball_center(std::span<const double> row) const { return Point(0, row[1] + radius_); }
  double radius() const { return radius_; }
  /// The impact times found in the pre-pass (from each step that rebounds,
  /// exactly: free fall is a parabola).
  const std::vector<double>& impacts() const { return impacts_; }

 private:
  double g_, period_;
  std::function<double(double)> exact_;
  SceneColors colors_;
  double highest_ = 0, fastest_ = 0;
  double radius_ = 0, per_speed_ = 0;
  std::vector<double> impacts_;
  std::vector<double> previous_;  ///< the pre-pass's previous row
  ForcesSeen seen_;               ///< over this run's rows: the key's entries
};

}  // namespace vibra::scenes
