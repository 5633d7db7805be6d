#include "core/analysis/model_convergence.hpp"

#include <cstdio>

#include "core/error.hpp"
#include "core/models/model.hpp"

namespace vibra {

ModelConvergence model_convergence(const std::string& model_name, const std::vector<std::string>& settings, int levels) {
  if (levels < 2 || levels > 20) throw UsageError("--levels must be 2..20 (each level halves dt), e.g. --levels 5");
  const ModelDefinition& model = find_model(model_name);
  Parameters base = model_parameters(model);
  for (const auto& s : settings) base.assign(s);
  const TrajectoryInfo info = model.build(base)->info();
  if (!info.exact || info.exact_label != "exact")
    throw UsageError("model " + model_name + " has no exact solution with these settings" +
                     (info.exact ? " (its " + info.exact_label + " solution is an approximation)" : "") +
                     ": use undamped, or two-body with a circular orbit (its default)");

  // Each level sets dt itself, so a user's dt or steps_per_period only fixes dt_0.
  Parameters per_level = model_parameters(model);
  for (const auto& s : settings) {
    std::string key = s.substr(0, s.find('='));
    std::erase(key, ' ');
    if (key != "dt" && key != "steps_per_period") per_level.assign(s);
  }
  auto make = [&](double dt) {
    Parameters p = per_level;
    char text[40];
    std::snprintf(text, sizeof text, "%.17g", dt);
    p.set("dt", text);
    return model.build(p);
  };
  const SchemeInfo& scheme = scheme_info(info.mesh.scheme);
  return {std::string(scheme.name), scheme.order, convergence_study(make, info.exact, info.mesh.dt, levels)};
}

}  // namespace vibra
