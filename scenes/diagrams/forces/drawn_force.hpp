// The forces a free-body diagram draws at one instant, and which of them a run draws at all (its key's entries).
#pragma once
#include <bitset>
#include <string>
#include <vector>

#include "scenes/diagrams/diagram.hpp"
#include "render/draw/annotations.hpp"
#include "render/draw/elements/shapes.hpp"
#include "scenes/diagrams/forces/force_key.hpp"

namespace vibra::scenes {

/// What a drawn force is: the key names each kind once (docs/drawing.md).
enum class ForceKind { weight, normal, friction, spring, damper, driving, count };

/// A force drawn at one instant: its arrow (world units) from where it acts
/// on the body, its colour and its label (Pango markup).
struct DrawnForce {
  ForceKind kind;
  Arrow arrow;
  render::Color color;
  std::string label;
};

/// A force on a small round body drawn from its rim: the arrow `centre` to
/// `tip` moved out along itself by `radius`, its length (the force's) kept,
/// so the body stays whole beside the arrows' casings.
inline Arrow from_rim(const Point& centre, double radius, const Point& tip) {
  const Point d = tip - centre;
  const double length = d.norm();
  if (!(length > 0)) return {centre, tip};
  const Point out = radius / length * d;
  return {centre + out, tip + out};
}

/// The gap (world units) between a body's rim and the tail of a force drawn
/// from it: the shaft's round cap and its casing, so neither covers the body.
inline double rim_gap(const render::Canvas& canvas, const render::WorldView& view) {
  const double scale = canvas.scale();
  return (render::Casing{}.device_reach(scale) + 0.5 * render::kForceShaftWidth * scale) / view.zoom();
}

/// What a spring's force label adds about the spring (section 1.12.1): a
/// spring from a wall to a body whose displacement u from its natural length
/// is `extension` pushes when compressed and pulls when stretched.
inline const char* spring_state(double extension) {
  return extension < 0 ? ", compressed" : extension > 0 ? ", stretched" : "";
}

/// One row of a diagram's key: the entry shown when the run drew `kind`.
struct KeyEntry {
  ForceKind kind;
  ForceName name;
};

/// The kinds of force a run drew, gathered over the pre-pass (a run's own
/// rows only): its key lists exactly these, so a run without friction, a
/// damper or a rest on the ground has no such entry.
class ForcesSeen {
 public:
  void see(ForceKind kind) { seen_.set(size_t(kind)); }
  bool has(ForceKind kind) const { return seen_.test(size_t(kind)); }
  /// The entries of `table` whose force the run drew, in the table's order.
  std::vector<ForceName> names(const std::vector<KeyEntry>& table) const {
    std::vector<ForceName> out;
    for (const KeyEntry& e : table)
      if (has(e.kind)) out.push_back(e.name);
    return out;
  }

 private:
  std::bitset<size_t(ForceKind::count)> seen_;
};

}  // namespace vibra::scenes
