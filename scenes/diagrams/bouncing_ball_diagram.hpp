#pragma once
#include <functional>
#include <vector>

#include "scenes/diagrams/diagram.hpp"
#include "scenes/scene_style.hpp"

namespace vibra::scenes {

/// The bouncing ball of section 1.12.9 for the `bouncing-ball` model: the
/// hatched ground, the ball resting on it at height h, its velocity arrow
/// (to one scale over the run) and the weight mg (a fixed length: one force
/// only, nothing to compare it with), a burst on the ground at each impact
/// that fades within a fifth of a period, and a tally of the impacts so far.
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

  /// The velocity arrow (to scale) and the weight, in world units.
  Arrow velocity_arrow(std::span<const double> row) const;
  Arrow weight_arrow(std::span<const double> row) const;
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
};

}  // namespace vibra::scenes
