// A model's Parameters from the user's settings with dt replaced, for experiments that vary dt.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "core/models/model.hpp"

namespace vibra {

/// The model's Parameters with the user's KEY=VALUE settings, but with dt
/// set to `dt`: a given dt or steps_per_period is dropped, as experiments
/// that vary dt (convergence, empirical periods) choose it themselves.
Parameters parameters_with_dt(const ModelDefinition&, const std::vector<std::string>& settings, double dt);

}  // namespace vibra
