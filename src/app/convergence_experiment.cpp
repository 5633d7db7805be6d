#include <cmath>
#include <cstdio>

#include "app/experiments.hpp"
#include "core/analysis/model_convergence.hpp"
#include "core/error.hpp"
#include "scenes/analysis_figures.hpp"

namespace vibra::app {

namespace {
/// Says plainly whether the last rates mean the scheme's order.
std::string settled_or_not(const ModelConvergence& study) {
  const auto& levels = study.levels;
  char text[320];
  if (study.settled)
    std::snprintf(text, sizeof text, "The rates have settled: r = %.2f over the last two levels (order %d).",
                  levels.back().rate, study.order);
  else if (levels.size() < 3)
    std::snprintf(text, sizeof text, "One rate cannot show whether the rates have settled: use 3 or more --levels.");
  else
    std::snprintf(text, sizeof text,
                  "The rates have NOT settled: the last two differ by %.2f (more than %.2f), so r is not yet the order; "
                  "use more --levels or a smaller dt.",
                  std::abs(levels.back().rate - levels[levels.size() - 2].rate), kSettledRateTolerance);
  return text;
}
}  // namespace

ExperimentResult convergence_experiment(const ConvergenceOptions& o) {
  if (o.model.empty())
    throw UsageError("vibra analyze convergence needs a MODEL, e.g. vibra analyze convergence undamped --set scheme=rk4");
  if (o.levels && (*o.levels < 2 || *o.levels > 20))
    throw UsageError("--levels must be 2..20 (each level halves dt), e.g. --levels 5");
  ModelConvergence study = model_convergence(o.model, o.settings, o.levels.value_or(0));
  Table table({"i", "dt", "E", "r"});
  for (size_t i = 0; i < study.levels.size(); ++i) {
    const ConvergenceLevel& level = study.levels[i];
    table.add_row({static_cast<long long>(i), level.dt, level.error, level.rate});
  }
  const std::string what = o.model + ", scheme " + study.scheme + " (order " + std::to_string(study.order) + ")";
  ExperimentResult result;
  result.tables.push_back(
      {"Convergence of " + what + ": E = sqrt(dt sum (u^n - u_e(t_n))^2), r = ln(E_{i-1}/E_i) / ln 2", std::move(table)});
  result.conclusion = settled_or_not(study);
  result.figure = [study = std::move(study), what](int w, int h) {
    return scenes::convergence_figure(study, "Convergence of " + what, w, h);
  };
  return result;
}

}  // namespace vibra::app
