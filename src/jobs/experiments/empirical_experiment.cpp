// vibra analyze empirical: periods and amplitudes measured from a run's extrema.
#include <cmath>
#include <cstdio>

#include "jobs/experiments/experiments.hpp"
#include "jobs/list_option.hpp"
#include "core/analysis/empirical.hpp"
#include "core/analysis/parameters_with_dt.hpp"
#include "core/analysis/frequency/phase_lag.hpp"
#include "core/error.hpp"
#include "core/models/model.hpp"
#include "scenes/figures/analysis_figures.hpp"

namespace vibra::app {

ExperimentResult empirical_experiment(const EmpiricalOptions& o) {
  if (o.model.empty())
    throw UsageError("vibra analyze empirical needs a MODEL, e.g. vibra analyze empirical undamped --dt 0.1,0.05");
  const ModelDefinition& model = find_model(o.model);
  // Without --dt, the one run the settings describe.
  std::vector<Parameters> runs;
  if (o.dt.empty())
    runs.push_back(model_settings(o.model, o.settings));
  else
    for (double dt : positive_list("--dt", o.dt)) runs.push_back(parameters_with_dt(model, o.settings, dt));

  const ExtremumTiming timing = o.mesh_extrema ? ExtremumTiming::mesh : ExtremumTiming::fitted;
  Table table({"dt", "i", "t", "period", "angular_frequency", "amplitude", "phase_lag"});
  std::vector<scenes::LabelledCycles> labelled;
  TrajectoryInfo info;
  for (const Parameters& p : runs) {
    auto trajectory = model.build(p);
    info = trajectory->info();
    const double dt = info.mesh.dt;
    auto cycles = oscillation_cycles(*trajectory, timing);
    if (cycles.empty()) {
      char message[200];
      std::snprintf(message, sizeof message,
                    "no complete oscillation (two maxima and a minimum) of %s with dt=%g: raise T or periods",
                    info.columns[1].c_str(), dt);
      throw UsageError(message);
    }
    // Against the exact solution's maxima where it is known (Exercise 1.2); empty otherwise.
    const bool exact = info.exact && info.exact_label == "exact" && info.exact_period > 0;
    for (const auto& c : cycles)
      table.add_row({dt, static_cast<long long>(c.i), c.t, c.period, 2 * M_PI / c.period, c.amplitude,
                     exact ? Table::Cell(phase_lag(info.exact, info.exact_period, c.t)) : Table::Cell(std::string())});
    char label[64];
    std::snprintf(label, sizeof label, "Δ<i>t</i> = %g", dt);
    labelled.push_back({label, std::move(cycles)});
  }
  const std::string scheme(scheme_info(info.mesh.scheme).name);
  ExperimentResult result;
  result.tables.push_back({"Empirical periods and amplitudes of " + info.columns[1] + " (" + o.model + ", " + scheme +
                               "), extrema " +
                               (o.mesh_extrema ? "at mesh points" : "placed by a sinusoid through three samples"),
                           std::move(table)});
  const double reference_w = info.mesh.period > 0 ? 2 * M_PI / info.mesh.period : 0;
  char reference[96];
  std::snprintf(reference, sizeof reference, "%s <i>ω</i> = %.4g", info.exact_label == "exact" ? "exact" : "small-oscillation",
                reference_w);
  result.figure = [labelled = std::move(labelled), reference_w, reference = std::string(reference),
                   title = "Empirical frequency and amplitude of " + o.model + ", " + scheme](int w, int h) {
    return scenes::empirical_figure(labelled, reference_w, reference, title, w, h);
  };
  return result;
}

}  // namespace vibra::app
