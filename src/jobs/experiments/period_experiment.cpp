// vibra analyze period: the pendulum's measured period against its exact one.
#include <cmath>
#include <cstdio>

#include "jobs/experiments/experiments.hpp"
#include "core/analysis/frequency/period_meter.hpp"
#include "core/error.hpp"
#include "core/models/model.hpp"
#include "scenes/figures/analysis_figures.hpp"
#include "scenes/overlays/run_caption.hpp"

namespace vibra::app {

ExperimentResult period_experiment(const PeriodOptions& o) {
  if (o.model.empty()) throw UsageError("vibra analyze period needs a MODEL, e.g. vibra analyze period pendulum --set alpha=0");
  const Parameters parameters = model_settings(o.model, o.settings);
  auto trajectory = find_model(o.model).build(parameters);
  const TrajectoryInfo info = trajectory->info();
  if (!std::isfinite(info.mesh.T)) throw UsageError("vibra analyze period needs a finite end time: give T or periods");
  std::vector<MeasuredPeriod> periods = measure_periods(*trajectory);
  if (periods.empty())
    throw UsageError("no complete period (two upward zero crossings) of " + info.columns[1] + ": raise T or periods");

  const double exact = info.exact_period > 0 ? info.exact_period : NAN;
  std::vector<std::string> columns = {"i", "t", "period", "exact"};
  if (info.damped) columns.push_back("log_decrement");
  Table table(columns);
  for (const auto& p : periods) {
    std::vector<Table::Cell> row = {static_cast<long long>(p.i), p.t, p.period, exact};
    if (info.damped) row.push_back(p.log_decrement);
    table.add_row(std::move(row));
  }
  char heading[320];
  std::snprintf(heading, sizeof heading,
                "Periods of %s between upward zero crossings (%s, %s, dt = %.4g); small-oscillation period %.10g%s",
                info.columns[1].c_str(), o.model.c_str(), std::string(scheme_info(info.mesh.scheme).name).c_str(),
                info.mesh.dt, info.mesh.period,
                info.damped ? "; log_decrement = ln(a_i/a_(i+1)) of the maxima in periods i and i+1" : "");
  ExperimentResult result;
  result.tables.push_back({heading, std::move(table)});
  const std::string title = "Measured periods: " + scenes::run_caption(o.model, parameters, info.mesh);
  result.figure = [periods = std::move(periods), info, title](int w, int h) {
    return scenes::period_figure(periods, info.exact_period, info.mesh.period, title, w, h);
  };
  return result;
}

}  // namespace vibra::app
