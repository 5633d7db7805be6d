#include "app/experiments.hpp"
#include "core/analysis/model_convergence.hpp"
#include "core/error.hpp"
#include "scenes/analysis_figures.hpp"

namespace vibra::app {

ExperimentResult convergence_experiment(const ConvergenceOptions& o) {
  if (o.model.empty())
    throw UsageError("vibra analyze convergence needs a MODEL, e.g. vibra analyze convergence undamped --set scheme=rk4");
  ModelConvergence study = model_convergence(o.model, o.settings, o.levels);
  Table table({"i", "dt", "E", "r"});
  for (size_t i = 0; i < study.levels.size(); ++i) {
    const ConvergenceLevel& level = study.levels[i];
    table.add_row({static_cast<long long>(i), level.dt, level.error, level.rate});
  }
  const std::string what = o.model + ", scheme " + study.scheme + " (order " + std::to_string(study.order) + ")";
  ExperimentResult result;
  result.tables.push_back(
      {"Convergence of " + what + ": E = sqrt(dt sum (u^n - u_e(t_n))^2), r = ln(E_{i-1}/E_i) / ln 2", std::move(table)});
  result.figure = [study = std::move(study), what](int w, int h) {
    return scenes::convergence_figure(study, "Convergence of " + what, w, h);
  };
  return result;
}

}  // namespace vibra::app
