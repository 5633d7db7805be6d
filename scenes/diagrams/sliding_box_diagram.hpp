#pragma once
#include <array>
#include <functional>
#include <optional>

#include "core/models/sliding_box_law.hpp"
#include "scenes/diagrams/diagram.hpp"
#include "scenes/diagrams/force_scale.hpp"
#include "scenes/horizontal_layout.hpp"
#include "scenes/scene_style.hpp"

namespace vibra::scenes {

/// The sliding box of section 1.12.3 for the `sliding-box` model: a box on a
/// hatched floor (no wheels), a spring to the wall, arrows for the spring
/// force -s(u) and the friction f along the floor (kinetic, -mu sign(u'),
/// while it slides; the static friction that holds it at rest), and the
/// normal force N and gravity mg. The scaled model knows forces in units of
/// the initial spring force only, not the weight, so N and mg are drawn at a
/// fixed length (equal and opposite), not to the force scale. Friction much
/// smaller than the spring force is magnified (by 2, 5, 10, ...) and its
/// label says so, as the pendulum's drag is.
class SlidingBoxDiagram final : public Diagram {
 public:
  SlidingBoxDiagram(SlidingBoxLaw, std::function<double(double)> exact, SceneColors);

  void record(std::span<const double> row, WorldBox& world) override;
  void finish_recording(WorldBox& world) override;
  void draw_static(render::Canvas&, const render::WorldView&) const override;
  void draw(render::Canvas&, const render::WorldView&, std::span<const double> row) override;
  std::vector<PanelSpec> panels() const override;
  std::optional<ForceKey> force_key() const override;

  /// Spring and friction arrows at a row (to scale, friction magnified), in world units.
  std::array<Arrow, 2> force_arrows(std::span<const double> row) const;
  double friction_magnification() const { return friction_magnification_; }

 private:
  SlidingBoxLaw law_;
  std::function<double(double)> exact_;
  SceneColors colors_;
  double largest_u_ = 0;
  ForceScale scale_;
  double friction_magnification_ = 1;  ///< friction drawn this many times longer when small, and labelled so
  std::optional<HorizontalLayout> layout_;
};

}  // namespace vibra::scenes
