// The models' help text: one line each, and each model's keys for --help.
#pragma once
#include <string>

#include "core/models/model.hpp"

namespace vibra::cli {

/// The models, one line each, for `vibra solve --help`.
std::string models_help();
/// A model's keys with meaning, unit and default, for `vibra solve MODEL --help`.
std::string model_keys_help(const ModelDefinition&);
/// A command's own --help on standard output: `usage`, then the models (no
/// `model`) or the model's keys.
void print_model_help(const std::string& usage, const std::string& model);

}  // namespace vibra::cli
