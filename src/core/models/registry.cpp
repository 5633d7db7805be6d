// The model registry: all_models() and lookup by name with a suggestion for a misspelt one.
#include "core/error.hpp"
#include "core/input/name_spelling.hpp"
#include "core/models/model.hpp"

namespace vibra {

const std::vector<ModelDefinition>& all_models() {
  static const std::vector<ModelDefinition> models = {undamped_model(),          vibration_model(),
                                                      pendulum_model(),          physical_pendulum_model(),
                                                      elastic_pendulum_model(), two_body_model(),
                                                      resonance_model(),        sliding_box_model(),
                                                      bumpy_road_model(),         bouncing_ball_model(),
                                                      rlc_model()};
  return models;
}

const ModelDefinition& find_model(const std::string& name) {
  std::vector<std::string> names;
  for (const auto& model : all_models()) {
    if (same_name(model.name, name)) return model;
    names.push_back(model.name);
  }
  std::string list;
  for (const auto& n : names) list += (list.empty() ? "" : ", ") + n;
  std::string near = closest_match(name, names);
  throw UsageError("unknown model '" + name + "'" + (near.empty() ? "" : " (did you mean '" + near + "'?)") +
                   ": choose one of " + list);
}

Parameters model_parameters(const ModelDefinition& model) {
  std::vector<KeySpec> keys = model.keys;
  for (auto& key : time_keys(model.time_defaults)) keys.push_back(std::move(key));
  return Parameters("model " + model.name, std::move(keys));
}

std::string model_equation(const ModelDefinition& model, const Parameters& p) {
  if (!model.equation_for) return model.equation;
  try {
    return model.equation_for(p);
  } catch (const UsageError&) {
    return model.equation;  // a setting the run itself will refuse: the general form meanwhile
  }
}

Parameters model_settings(const std::string& model_name, const std::vector<std::string>& assignments) {
  Parameters p = model_parameters(find_model(model_name));
  for (const auto& a : assignments) p.assign(a);
  return p;
}

}  // namespace vibra
