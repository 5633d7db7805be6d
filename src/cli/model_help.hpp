#pragma once
#include <string>

#include "core/models/model.hpp"

namespace vibra::cli {

/// The models, one line each, for `vibra solve --help`.
std::string models_help();
/// A model's keys with meaning, unit and default, for `vibra solve MODEL --help`.
std::string model_keys_help(const ModelDefinition&);

}  // namespace vibra::cli
