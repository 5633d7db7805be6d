// vibra analyze resonance: steady amplitudes against the forcing frequency (Exercise 1.22).
#include "jobs/experiments/experiments.hpp"
#include "jobs/list_option.hpp"
#include "core/analysis/resonance.hpp"
#include "scenes/figures/resonance_figure.hpp"

namespace vibra::app {

ExperimentResult resonance_experiment(const ResonanceOptions& o) {
  const std::vector<double> betas = positive_list("--beta", o.beta), gammas = positive_list("--gamma", o.gamma);
  std::vector<ResonancePoint> points;
  Table table({"beta", "gamma", "amplitude", "exact"});
  for (double beta : betas)
    for (double gamma : gammas) {
      points.push_back(measure_steady_amplitude(beta, gamma));
      table.add_row({beta, gamma, points.back().amplitude, points.back().exact});
    }
  ExperimentResult result;
  result.tables.push_back({"Steady amplitude of u'' + beta u' + u = sin(gamma t) after the transient (RK4), against "
                           "1/sqrt((1 - gamma^2)^2 + (beta gamma)^2)",
                           std::move(table)});
  result.figure = [points](int width, int height) { return scenes::resonance_figure(points, width, height); };
  return result;
}

}  // namespace vibra::app
