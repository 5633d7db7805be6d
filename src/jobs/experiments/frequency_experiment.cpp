// vibra analyze frequency: the centered scheme's numerical frequency (1.18) against w.
#include <cmath>
#include <cstdio>

#include "jobs/experiments/experiments.hpp"
#include "jobs/list_option.hpp"
#include "core/analysis/frequency/numerical_frequency.hpp"
#include "core/error.hpp"
#include "core/input/expression.hpp"
#include "scenes/figures/analysis_figures.hpp"

namespace vibra::app {

ExperimentResult frequency_experiment(const FrequencyOptions& o) {
  const double w = evaluate_constant("--w", o.w);
  if (!(w > 0) || !std::isfinite(w)) throw UsageError("--w must be a positive number, e.g. --w 1");
  std::vector<double> steps = positive_list("--steps-per-period", o.steps_per_period);
  for (double n : steps)
    if (n < M_PI)
      throw UsageError("--steps-per-period " + std::to_string(n) +
                       " is below pi, the stability limit (dt = 2/w): give values >= 3.1416");
  steps.push_back(M_PI);  // the stability limit dt = 2/w
  Table table({"dt", "steps_per_period", "w_tilde", "w_series", "w_tilde_rel_error", "w_series_rel_error"});
  for (double n : steps) {
    const double dt = n == M_PI ? 2 / w : 2 * M_PI / (w * n);
    const double exact = numerical_frequency(w, dt), series = numerical_frequency_series(w, dt);
    table.add_row({dt, n, exact, series, exact / w - 1, series / w - 1});
  }
  char heading[160];
  std::snprintf(heading, sizeof heading,
                "Centered scheme's frequency w~ = (2/dt) asin(w dt/2) (1.18) and series w (1 + w^2 dt^2/24) (1.19), "
                "w = %g; last row: the stability limit dt = 2/w",
                w);
  ExperimentResult result;
  result.tables.push_back({heading, std::move(table)});
  result.figure = [w](int width, int height) { return scenes::frequency_figure(w, width, height); };
  return result;
}

}  // namespace vibra::app
