// The diagram registry: what a diagram is built from, and each diagram found by name.
#pragma once
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "core/input/parameters.hpp"
#include "core/trajectory.hpp"
#include "scenes/diagrams/diagram.hpp"
#include "scenes/config/scene_config.hpp"

namespace vibra::scenes {

/// What a diagram is made from: the scene (colours, options), the model's
/// settings (the diagram reads the same force laws the model solves) and
/// what the model tells of the run.
struct DiagramInput {
  const SceneConfig& config;
  const Parameters& parameters;
  const TrajectoryInfo& info;
};

/// A kind of drawing: its name (the scene key `diagram`), the models whose
/// rows it draws, and how to make one. The first kind that lists a model is
/// that model's default drawing.
struct DiagramKind {
  std::string name;
  std::string summary;
  std::vector<std::string> models;
  std::function<std::unique_ptr<Diagram>(const DiagramInput&)> make;
  /// The `annotate` names it draws (e.g. "geometry"); none by default.
  std::vector<std::string> annotations = {};
  /// Whether it draws small motions larger (`exaggerate`); the others are true to scale.
  bool exaggerates = false;
};

/// Every diagram, in the order `vibra render --help` lists them.
const std::vector<DiagramKind>& all_diagrams();
/// The model's default diagram, or nullptr when the model has none.
const DiagramKind* default_diagram(const std::string& model);
/// The diagram a scene asks for (`diagram`, or the model's default). Throws
/// UsageError for an unknown name (with the closest one), a diagram that
/// cannot draw the model, or a model without a diagram.
const DiagramKind& diagram_for(const SceneConfig&);

// One function per kind, defined beside each diagram.
DiagramKind pendulum_diagram_kind();
DiagramKind oscillator_diagram_kind();
DiagramKind washing_machine_diagram_kind();
DiagramKind sliding_box_diagram_kind();
DiagramKind bumpy_road_diagram_kind();
DiagramKind bouncing_ball_diagram_kind();
DiagramKind rlc_diagram_kind();
DiagramKind elastic_pendulum_diagram_kind();
DiagramKind orbit_diagram_kind();

}  // namespace vibra::scenes
