// The bumpy road's diagram (section 1.12.8): road, wheel, spring, dashpot and body.
#pragma once
#include <memory>
#include <optional>

#include "core/models/road_profile.hpp"
#include "render/draw/elements/ground_profile.hpp"
#include "scenes/diagrams/diagram.hpp"
#include "scenes/diagrams/forces/drawn_force.hpp"
#include "scenes/diagrams/forces/force_scale.hpp"
#include "scenes/config/scene_style.hpp"

namespace vibra::scenes {

/// A vehicle on a bumpy road (section 1.12.8) for the `bumpy-road` model:
/// the road profile, a wheel of radius R rolling on it at x = s t, a spring
/// and a damper from the axle up to the body, whose height over the axle is
/// L + u; arrows on the body for the spring force -k u and the damper force
/// -b u' (in newtons, to one scale; no damper arrow when b = 0). u is
/// measured from the rest height, where the spring's static load balances
/// the weight mg: the two cancel and neither is drawn (the key's name for -k u says so). The view follows the vehicle; heights
/// are fixed from the pre-pass. Heights (the road's and the body's u) are
/// drawn `exaggeration()` times larger, said in the force key: a few
/// centimetres under a metre-high vehicle would otherwise be a few pixels.
/// Rows: t, u, v, x, h.
class BumpyRoadDiagram final : public Diagram {
 public:
  struct Vehicle {
    double k, b, R, L;
  };
  /// `exaggerate`: the factor for heights; 0 chooses it from the run (automatic_exaggeration).
  BumpyRoadDiagram(std::shared_ptr<const RoadProfile>, Vehicle, SceneColors, double exaggerate = 1);

  void record(std::span<const double> row, WorldBox& world) override;
  void finish_recording(WorldBox& world) override;
  std::optional<FollowingView> view_at(std::span<const double> row) const override;
  void draw(render::Canvas&, const render::WorldView&, std::span<const double> row) override;
  std::vector<PanelSpec> panels() const override;
  std::optional<ForceKey> force_key() const override;

  Point axle(std::span<const double> row) const { return {row[3], factor_ * row[4] + vehicle_.R}; }
  double body_bottom(std::span<const double> row) const { return axle(row).y() + vehicle_.L + factor_ * row[1]; }
  /// How many times larger heights are drawn (known after finish_recording).
  double exaggeration() const { return factor_; }
  /// The factor `exaggerate = 0` chooses: 1 when the body's swing already
  /// shows (a seventh of L or more), else the largest of 1, 2, 3, 4, 5 times
  /// a power of ten that keeps the swing within half of L and the road's
  /// bumps within 0.8 R, so that the drawing stays a vehicle on a road.
  static double automatic_exaggeration(double swing, double bumps, const Vehicle&);
  /// Where the spring (left) and the damper (right) stand, from the axle's
  /// centre: outside the wheel, so that neither crosses its rim.
  double strut_offset() const { return 0.4 * body_width_; }
  /// The wheel's turn at road position x, radians: rolling without slipping,
  /// clockwise (negative) as the vehicle drives right.
  double wheel_turn(double x) const { return -x / vehicle_.R; }
  /// The spring's force and (when b > 0) the damper's at a row, in world units.
  std::vector<DrawnForce> forces(std::span<const double> row) const;

 private:
  std::shared_ptr<const RoadProfile> road_;
  Vehicle vehicle_;
  SceneColors colors_;
  ForceScale scale_;
  std::optional<render::GroundProfile> ground_;  ///< once the run's heights are known
  double requested_ = 1, factor_ = 1;
  double low_ = 1e300, high_ = -1e300;
  double lowest_road_ = 1e300, highest_road_ = -1e300, highest_top_ = -1e300, swing_ = 0;  ///< raw, from the pre-pass
  double half_width_ = 1, body_width_ = 1, body_height_ = 0.3;
};

}  // namespace vibra::scenes
