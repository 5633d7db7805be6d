// The forces a free-body diagram draws at one instant, and which of them a run draws at all (its key's entries).
#pragma once
#include <bitset>
#include <string>
#include <vector>

#include "scenes/diagrams/diagram.hpp"
#include "scenes/diagrams/force_key.hpp"

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
