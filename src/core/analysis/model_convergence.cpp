// A convergence study of one model and scheme, as vibra analyze convergence runs it.
#include "core/analysis/model_convergence.hpp"

#include <string>

#include "core/analysis/parameters_with_dt.hpp"
#include "core/error.hpp"
#include "core/input/value_ranges.hpp"
#include "core/models/model.hpp"

namespace vibra {

ModelConvergence model_convergence(const std::string& model_name, const std::vector<std::string>& settings, int levels) {
  if (levels != 0) in_range("--levels", levels, std::to_string(levels));  // 0: halve until the rates agree
  const ModelDefinition& model = find_model(model_name);
  Parameters base = model_parameters(model);
  for (const auto& s : settings) base.assign(s);
  const TrajectoryInfo info = model.build(base)->info();
  require_even_steps(info.mesh, "analyze convergence, which halves dt,");
  // A labelled approximation (the pendulum's small-angle solution) would make
  // the error stall at the approximation's own error: it does not count.
  if (!info.exact || info.exact_label != "exact")
    throw UsageError("model " + model_name + " has no exact solution with these settings" +
                     (info.exact ? " (its " + info.exact_label + " solution is an approximation)" : "") +
                     ": use undamped, vibration with a linear spring and no forcing (or undamped with F=A*sin(phi*t)), rlc without a "
                     "source (V=0), resonance, sliding-box released from rest, or two-body with a circular orbit (its default)");

  auto make = [&](double dt) { return model.build(parameters_with_dt(model, settings, dt)); };
  const SchemeInfo& scheme = scheme_info(info.mesh.scheme);
  ModelConvergence study{std::string(scheme.name), info.velocity_damping ? damped_order(scheme) : scheme.order,
                         levels == 0 ? convergence_until_settled(make, info.exact, info.mesh.dt, kAutoMinLevels, kAutoMaxLevels)
                                     : convergence_study(make, info.exact, info.mesh.dt, levels)};
  study.settled = rates_settled(study.levels);
  return study;
}

}  // namespace vibra
