#pragma once
#include <string>

#include "core/models/model.hpp"

namespace vibra::cli {

/// The models, one line each, for `vibra solve --help`.
std::string models_help();
/// A model's keys with meaning, unit and default, for `vibra solve MODEL --help`.
std::string model_keys_help(const ModelDefinition&);

/// Parameters for `model_name` with the user's KEY=VALUE settings applied.
Parameters model_settings(const std::string& model_name, const std::vector<std::string>& assignments);

}  // namespace vibra::cli
