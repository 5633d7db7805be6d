// The models' help text: one line each, and each model's keys for --help.
#include "cli/manuals/model_help.hpp"

#include <cstdio>

#include "render/output/standard_output.hpp"

namespace vibra::cli {

std::string models_help() {
  std::string out = "Models:\n";
  char line[256];
  for (const auto& model : all_models()) {
    std::snprintf(line, sizeof line, "  %-18s %s\n", model.name.c_str(), model.summary.c_str());
    out += line;
  }
  out += "\nSchemes (--set scheme=NAME):\n";
  for (const auto& scheme : all_schemes()) {
    std::snprintf(line, sizeof line, "  %-18s order %d  %s\n", std::string(scheme.name).c_str(), scheme.order,
                  summary_with_damped_order(scheme).c_str());
    out += line;
  }
  return out;
}

std::string model_keys_help(const ModelDefinition& model) {
  std::string out = "Model " + model.name + ": " + model.summary + "\nColumns: ";
  for (size_t i = 0; i < model.columns.size(); ++i) out += (i ? "," : "") + model.columns[i];
  // As render --equation typesets it (the LaTeX subset of docs/drawing.md).
  out += "\nEquation: " + model.equation;
  out += "\n\nKeys (--set KEY=VALUE; values may be expressions such as 2*pi/40):\n";
  char line[512];
  const Parameters parameters = model_parameters(model);
  for (const auto& key : parameters.specs()) {
    std::string meaning = key.meaning;
    if (!key.choices.empty() && key.choices.size() <= 4) {
      meaning += " (";
      for (size_t i = 0; i < key.choices.size(); ++i) meaning += (i ? "|" : "") + key.choices[i];
      meaning += ")";
    }
    std::snprintf(line, sizeof line, "  %-17s %-60s unit: %-10s default: %s\n", key.name.c_str(), meaning.c_str(),
                  key.unit.empty() ? "-" : key.unit.c_str(), key.default_value.empty() ? "-" : key.default_value.c_str());
    out += line;
  }
  return out;
}

void print_model_help(const std::string& usage, const std::string& model) {
  render::print_standard_output(usage + (model.empty() ? models_help() : model_keys_help(find_model(model))));
}

}  // namespace vibra::cli
