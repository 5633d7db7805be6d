// A model's Parameters from the user's settings with dt replaced, for experiments that vary dt.
#include "core/analysis/parameters_with_dt.hpp"

#include <cstdio>

namespace vibra {

Parameters parameters_with_dt(const ModelDefinition& model, const std::vector<std::string>& settings, double dt) {
  Parameters p = model_parameters(model);
  for (const auto& s : settings) {
    std::string key = s.substr(0, s.find('='));
    std::erase(key, ' ');
    if (key != "dt" && key != "steps_per_period") p.assign(s);
  }
  char text[40];
  std::snprintf(text, sizeof text, "%.17g", dt);
  p.set("dt", text);
  return p;
}

}  // namespace vibra
