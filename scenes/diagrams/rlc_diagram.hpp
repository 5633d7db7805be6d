// The series RLC circuit's diagram (section 1.12.11): source, resistor, inductor, capacitor, current and charge.
#pragma once
#include "render/draw/elements/circuit_elements.hpp"
#include "scenes/diagrams/diagram.hpp"
#include "scenes/config/scene_style.hpp"

namespace vibra::scenes {

/// The series RLC circuit of section 1.12.11 for the `rlc` model: a loop
/// with the source V(t) on the left (+ at the top), the resistor R on top,
/// the inductor L on the right and the capacitor C at the bottom. Positive
/// current runs clockwise and charges the capacitor's right plate with +q.
/// An arrow inside the loop under the resistor has a length and a direction
/// that follow I (one scale over the run); the plates carry up to five signs
/// in proportion to |q| (of the largest over the run). Panels: I, q and V.
/// Rows are the model's: t, q, I, V.
class RlcDiagram final : public Diagram {
 public:
  explicit RlcDiagram(SceneColors);

  void record(std::span<const double> row, WorldBox& world) override;
  void finish_recording(WorldBox& world) override;
  void draw_static(render::Canvas&, const render::WorldView&) const override;
  void draw(render::Canvas&, const render::WorldView&, std::span<const double> row) override;
  std::vector<PanelSpec> panels() const override;

  /// The current's arrow at a row (world units): clockwise for I > 0.
  render::CurrentArrow current_arrow(std::span<const double> row) const;
  /// The capacitor at a row: which plate is positive, how many signs.
  render::CapacitorGeometry capacitor(std::span<const double> row) const;
  /// q over the run's largest |q| (0 when it never charges): the plates' tint and signs.
  double charge_share(std::span<const double> row) const { return largest_q_ > 0 ? row[1] / largest_q_ : 0; }
  static constexpr double kLongestCurrent = 1.6;  ///< the arrow of the largest |I|, world units

 private:
  SceneColors colors_;
  double largest_q_ = 0, largest_I_ = 0;
};

}  // namespace vibra::scenes
