// Steady amplitudes of u'' + beta u' + u = sin(gamma t) measured from runs (Exercise 1.22).
#include "core/analysis/resonance.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "core/models/model.hpp"

namespace vibra {

ResonancePoint measure_steady_amplitude(double beta, double gamma) {
  if (!(beta > 0) || !std::isfinite(beta)) throw UsageError("beta must be > 0: without damping there is no steady state");
  if (!(gamma > 0) || !std::isfinite(gamma)) throw UsageError("gamma must be > 0");
  const double settle = 2 * std::log(1e5) / beta;
  const double forcing_period = 2 * M_PI / gamma;
  const double dt = 2 * M_PI / (200 * std::max(1.0, gamma));
  const double T = settle + 5 * forcing_period;
  Parameters p = model_parameters(find_model("resonance"));
  p.set("beta", std::to_string(beta));
  p.set("gamma", std::to_string(gamma));
  p.set("scheme", "rk4");
  p.set("dt", std::to_string(dt));
  p.set("T", std::to_string(T));
  auto run = find_model("resonance").build(p);
  double low = 1e300, high = -1e300;
  std::vector<double> row(run->width());
  do {
    run->row(row);
    if (row[0] >= settle) low = std::min(low, row[1]), high = std::max(high, row[1]);
  } while (run->advance());
  return {beta, gamma, 0.5 * (high - low), steady_amplitude(beta, gamma)};
}

}  // namespace vibra
