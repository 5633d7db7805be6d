// The diagram registry: what a diagram is built from, and each diagram found by name.
#include "scenes/diagrams/diagram_registry.hpp"

#include <algorithm>

#include "core/error.hpp"

namespace vibra::scenes {

const std::vector<DiagramKind>& all_diagrams() {
  static const std::vector<DiagramKind> kinds = {pendulum_diagram_kind(),       oscillator_diagram_kind(),
                                                 washing_machine_diagram_kind(), sliding_box_diagram_kind(),
                                                 bumpy_road_diagram_kind(),    bouncing_ball_diagram_kind(),
                                                 rlc_diagram_kind(),              elastic_pendulum_diagram_kind(),
                                                 orbit_diagram_kind()};
  return kinds;
}

const DiagramKind* default_diagram(const std::string& model) {
  for (const auto& kind : all_diagrams())
    if (std::find(kind.models.begin(), kind.models.end(), model) != kind.models.end()) return &kind;
  return nullptr;
}

const DiagramKind& diagram_for(const SceneConfig& config) {
  std::string names;
  for (const auto& kind : all_diagrams()) names += (names.empty() ? "" : ", ") + kind.name;
  if (config.diagram.empty()) {
    if (const DiagramKind* kind = default_diagram(config.model)) return *kind;
    throw UsageError("model " + config.model + " has no free-body diagram: use --layout plot (diagrams: " + names + ")");
  }
  for (const auto& kind : all_diagrams()) {
    if (kind.name != config.diagram) continue;
    if (std::find(kind.models.begin(), kind.models.end(), config.model) == kind.models.end()) {
      std::string models;
      for (const auto& m : kind.models) models += (models.empty() ? "" : ", ") + m;
      throw UsageError("diagram " + kind.name + " draws model " + models + ", not " + config.model +
                       ": set model accordingly or choose another diagram");
    }
    return kind;
  }
  std::vector<std::string> list;
  for (const auto& kind : all_diagrams()) list.push_back(kind.name);
  const std::string near = closest_match(config.diagram, list);
  throw UsageError("unknown diagram '" + config.diagram + "'" + (near.empty() ? "" : " (did you mean '" + near + "'?)") +
                   ": choose one of " + names);
}

}  // namespace vibra::scenes
