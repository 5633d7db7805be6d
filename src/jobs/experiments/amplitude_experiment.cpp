// vibra analyze amplitude: empirical amplitudes from the extrema of a run.
#include "jobs/experiments/experiments.hpp"
#include "jobs/list_option.hpp"
#include "core/analysis/empirical.hpp"
#include "core/error.hpp"
#include "core/models/model.hpp"
#include "scenes/figures/analysis_figures.hpp"

namespace vibra::app {

ExperimentResult amplitude_experiment(const AmplitudeOptions& o) {
  const double I = 1;
  Table table({"scheme", "i", "t", "amplitude", "amplitude_error"});
  std::vector<scenes::LabelledCycles> runs;
  for (const auto& scheme : word_list("--schemes", o.schemes)) {
    const Parameters p = model_settings("undamped", {"scheme=" + scheme, "dt=" + o.dt, "periods=" + o.periods, "I=1", "V=0"});
    auto trajectory = find_model("undamped").build(p);
    auto cycles = oscillation_cycles(*trajectory);
    if (cycles.empty()) throw UsageError("no complete oscillation with --periods " + o.periods + ": give at least 2 periods");
    for (const auto& c : cycles) table.add_row({scheme, static_cast<long long>(c.i), c.t, c.amplitude, c.amplitude - I});
    runs.push_back({scheme, std::move(cycles)});
  }
  ExperimentResult result;
  result.tables.push_back(
      {"Empirical amplitudes a_i (exact: 1) of u'' + (2 pi)^2 u = 0, u(0) = 1, u'(0) = 0, dt = " + o.dt, std::move(table)});
  result.figure = [runs = std::move(runs), I,
                   title = "Amplitude of <i>u</i>'' + (2π)<sup>2</sup><i>u</i> = 0, Δ<i>t</i> = " + o.dt](int w, int h) {
    return scenes::amplitude_figure(runs, I, title, w, h);
  };
  return result;
}

}  // namespace vibra::app
