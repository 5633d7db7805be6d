// vibra analyze convergence: errors and rates of a scheme as dt halves, with a verdict on its order.
#include <cmath>
#include <cstdio>

#include "jobs/experiments/experiments.hpp"
#include "jobs/list_option.hpp"
#include "core/analysis/model_convergence.hpp"
#include "core/error.hpp"
#include "scenes/figures/analysis_figures.hpp"

namespace vibra::app {

namespace {
/// Says plainly whether the last rates mean the scheme's order.
std::string settled_or_not(const ModelConvergence& study, const std::string& who) {
  const auto& levels = study.levels;
  char text[320];
  if (study.settled)
    std::snprintf(text, sizeof text, "%sThe rates have settled: r = %.2f over the last two levels (order %d).",
                  who.c_str(), levels.back().rate, study.order);
  else if (levels.size() < 3)
    std::snprintf(text, sizeof text, "%sOne rate cannot show whether the rates have settled: use 3 or more --levels.",
                  who.c_str());
  else
    std::snprintf(text, sizeof text,
                  "%sThe rates have NOT settled: the last two differ by %.2f (more than %.2f), so r is not yet the order; "
                  "use more --levels or a smaller dt.",
                  who.c_str(), std::abs(levels.back().rate - levels[levels.size() - 2].rate), kSettledRateTolerance);
  return text;
}

/// The schemes of `--compare scheme=A,B`, or none without --compare.
std::vector<std::string> compared_schemes(const std::string& compare) {
  if (compare.empty()) return {};
  const std::string key = "scheme=";
  if (compare.rfind(key, 0) != 0)
    throw UsageError("analyze convergence compares schemes only: give --compare scheme=A,B, e.g. "
                     "--compare scheme=centered,centered-adjusted");
  std::vector<std::string> schemes = word_list("--compare", compare.substr(key.size()));
  if (schemes.size() < 2 || schemes.size() > 8)
    throw UsageError("--compare needs 2 to 8 schemes, e.g. --compare scheme=centered,centered-adjusted");
  return schemes;
}
}  // namespace

ExperimentResult convergence_experiment(const ConvergenceOptions& o) {
  if (o.model.empty())
    throw UsageError("vibra analyze convergence needs a MODEL, e.g. vibra analyze convergence undamped --set scheme=rk4");
  const std::vector<std::string> schemes = compared_schemes(o.compare);
  std::vector<ModelConvergence> studies;
  if (schemes.empty()) studies.push_back(model_convergence(o.model, o.settings, o.levels.value_or(0)));
  for (const auto& scheme : schemes) {
    std::vector<std::string> settings = o.settings;
    settings.push_back("scheme=" + scheme);  // the last assignment wins over a --set scheme
    studies.push_back(model_convergence(o.model, settings, o.levels.value_or(0)));
  }
  const bool compare = !schemes.empty();
  Table table(compare ? std::vector<std::string>{"scheme", "i", "dt", "E", "r"} : std::vector<std::string>{"i", "dt", "E", "r"});
  std::string conclusion;
  for (const ModelConvergence& study : studies) {
    for (size_t i = 0; i < study.levels.size(); ++i) {
      const ConvergenceLevel& level = study.levels[i];
      std::vector<Table::Cell> row = {static_cast<long long>(i), level.dt, level.error, level.rate};
      if (compare) row.insert(row.begin(), study.scheme);
      table.add_row(std::move(row));
    }
    conclusion += (conclusion.empty() ? "" : "\n") + settled_or_not(study, compare ? study.scheme + ": " : "");
  }
  const ModelConvergence& first = studies.front();
  std::string scheme_names;  // as parsed: "centered,rk4" whatever the spacing typed
  for (const ModelConvergence& study : studies) scheme_names += (scheme_names.empty() ? "" : ",") + study.scheme;
  const std::string what = compare ? o.model + ", schemes " + scheme_names
                                   : o.model + ", scheme " + first.scheme + " (order " + std::to_string(first.order) + ")";
  ExperimentResult result;
  result.tables.push_back(
      {"Convergence of " + what + ": E = sqrt(dt sum (u^n - u_e(t_n))^2), r = ln(E_{i-1}/E_i) / ln 2", std::move(table)});
  result.conclusion = conclusion;
  result.figure = [studies = std::move(studies), what](int w, int h) {
    return scenes::convergence_figure(studies, "Convergence of " + what, w, h);
  };
  return result;
}

}  // namespace vibra::app
