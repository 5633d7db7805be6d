// ModelDefinition: a model's keys, units, columns, time defaults and how to build its trajectory.
#pragma once
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "core/input/parameters.hpp"
#include "core/time_mesh.hpp"
#include "core/trajectory.hpp"

namespace vibra {

/// A model of the chapter as the command line sees it: its keys with their
/// defaults and units, its output columns, and how to build its trajectory.
struct ModelDefinition {
  std::string name;
  std::string summary;
  std::vector<KeySpec> keys;  ///< model keys; the time keys are added by the registry
  std::vector<std::string> columns;
  TimeDefaults time_defaults;
  std::function<std::unique_ptr<Trajectory>(const Parameters&)> build;
  /// The equation of motion in the typesetter's LaTeX subset (docs/drawing.md),
  /// e.g. "u'' + \omega^2 u = 0", as the book writes it.
  std::string equation;
  /// The equation for given settings, when they change its form (the damping
  /// law chosen, a force of zero); unset: `equation` whatever the settings.
  std::function<std::string(const Parameters&)> equation_for;
  /// The unit of time of a model in SI units ("s"); "" for a scaled model.
  std::string time_unit;
};

/// The model's equation of motion for these settings (ModelDefinition::equation_for, else equation).
std::string model_equation(const ModelDefinition&, const Parameters&);

/// Every model, in the order `--help` lists them.
const std::vector<ModelDefinition>& all_models();
/// Throws UsageError naming the valid models (and the closest one).
const ModelDefinition& find_model(const std::string& name);
/// Empty settings for a model: its keys plus the time keys.
Parameters model_parameters(const ModelDefinition&);
/// Settings for `model_name` with the user's KEY=VALUE assignments applied.
Parameters model_settings(const std::string& model_name, const std::vector<std::string>& assignments);

/// Throws UsageError when a model other than `undamped` is asked for centered-adjusted.
void reject_adjusted_scheme(const TimeMesh&, const std::string& model);

ModelDefinition undamped_model();
ModelDefinition vibration_model();
ModelDefinition pendulum_model();
ModelDefinition physical_pendulum_model();
ModelDefinition elastic_pendulum_model();
ModelDefinition two_body_model();
ModelDefinition resonance_model();
ModelDefinition sliding_box_model();
ModelDefinition bumpy_road_model();
ModelDefinition bouncing_ball_model();
ModelDefinition rlc_model();

class RoadProfile;
/// The road a bumpy-road run drives on (its keys road, A, wavelength, seed,
/// dx), at least `length` metres long for generated roads.
RoadProfile road_of(const Parameters&, double length);

/// Steady amplitude of u'' + beta u' + u = sin(gamma t):
/// 1 / sqrt((1 - gamma^2)^2 + (beta gamma)^2) (section 1.12.4).
double steady_amplitude(double beta, double gamma);

}  // namespace vibra
