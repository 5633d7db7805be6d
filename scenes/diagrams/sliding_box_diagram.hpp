// The sliding box's diagram (section 1.12.3): box on a floor, spring to the wall, spring and friction forces.
#pragma once
#include <functional>
#include <optional>

#include "core/models/sliding_box_law.hpp"
#include "scenes/diagrams/diagram.hpp"
#include "scenes/diagrams/forces/drawn_force.hpp"
#include "scenes/diagrams/forces/force_scale.hpp"
#include "scenes/overlays/horizontal_layout.hpp"
#include "scenes/config/scene_style.hpp"

namespace vibra::scenes {

/// The sliding box of section 1.12.3 for the `sliding-box` model: a box on a
/// hatched floor (no wheels), a spring to the wall, arrows for the spring
/// force -s(u) and the friction f along the floor, labelled by phase:
/// kinetic, -mu N sign(u'), while it slides; at a turning point that static
/// friction cannot hold (|s(u)| > mu), mu N against the coming motion; once
/// stuck, the static friction s(u), equal and opposite to the spring force
/// and at most mu N. The normal force N acts up from the floor where the box
/// stands on it, from the friction's point, the weight mg down from its centre. The scaled model knows forces in units of
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

  /// How the box moves at a row: friction is kinetic, at its limit or static.
  enum class Phase { sliding, stuck, turning };
  Phase phase(std::span<const double> row) const;
  /// The forces at a row, in world units: the spring's and the friction's to
  /// scale (friction magnified) when they are not zero, mg and N always.
  std::vector<DrawnForce> forces(std::span<const double> row) const;
  double friction_magnification() const { return friction_magnification_; }

 private:
  SlidingBoxLaw law_;
  std::function<double(double)> exact_;
  SceneColors colors_;
  double largest_u_ = 0;
  ForceScale scale_;
  double friction_magnification_ = 1;  ///< friction drawn this many times longer when small, and labelled so
  std::optional<HorizontalLayout> layout_;
  ForcesSeen seen_;  ///< over this run's rows: the key's entries

  /// The kinds of force acting at a row (not zero), in the order drawn.
  std::vector<ForceKind> present(std::span<const double> row) const;
};

}  // namespace vibra::scenes
