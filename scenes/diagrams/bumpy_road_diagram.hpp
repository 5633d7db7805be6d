#pragma once
#include <array>
#include <memory>
#include <optional>

#include "core/road_profile.hpp"
#include "render/draw/ground_profile.hpp"
#include "scenes/diagrams/diagram.hpp"
#include "scenes/diagrams/force_scale.hpp"
#include "scenes/scene_style.hpp"

namespace vibra::scenes {

/// A vehicle on a bumpy road (section 1.12.8) for the `bumpy-road` model:
/// the road profile, a wheel of radius R rolling on it at x = s t, a spring
/// and a damper from the axle up to the body, whose height over the axle is
/// L + u; arrows on the body for the spring force -k u and the damper force
/// -b u' (in newtons, to one scale). The view follows the vehicle; heights
/// are fixed from the pre-pass. Rows: t, u, v, x, h.
class BumpyRoadDiagram final : public Diagram {
 public:
  struct Vehicle {
    double k, b, R, L;
  };
  BumpyRoadDiagram(std::shared_ptr<const RoadProfile>, Vehicle, SceneColors);

  void record(std::span<const double> row, WorldBox& world) override;
  void finish_recording(WorldBox& world) override;
  std::optional<WorldBox> view_at(std::span<const double> row) const override;
  void draw(render::Canvas&, const render::WorldView&, std::span<const double> row) override;
  std::vector<PanelSpec> panels() const override;
  std::optional<ForceKey> force_key() const override;

  Point axle(std::span<const double> row) const { return {row[3], row[4] + vehicle_.R}; }
  double body_bottom(std::span<const double> row) const { return axle(row).y() + vehicle_.L + row[1]; }
  /// Spring and damper force arrows at a row, in world units.
  std::array<Arrow, 2> force_arrows(std::span<const double> row) const;

 private:
  std::shared_ptr<const RoadProfile> road_;
  Vehicle vehicle_;
  SceneColors colors_;
  ForceScale scale_;
  std::optional<render::GroundProfile> ground_;  ///< once the run's heights are known
  double low_ = 1e300, high_ = -1e300;
  double half_width_ = 1, body_width_ = 1, body_height_ = 0.3;
};

}  // namespace vibra::scenes
