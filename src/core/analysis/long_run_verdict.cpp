// What a long orbit run's blocks support: the phase drift's line, the energy error's trend, and the sentence.
#include "core/analysis/long_run_verdict.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

namespace vibra {

namespace {
// Two points on the unit circle are never further apart than this.
constexpr double kOrbitDiameter = 2.0;
}  // namespace

double chord(double phase) { return std::min(kOrbitDiameter, std::abs(2 * std::sin(phase / 2))); }

LongRunVerdict judge_long_run(const OrbitRun& run) {
  std::vector<double> orbits, phases;
  double first_half = 0, second_half = 0;
  const double middle = run.blocks.back().orbits / 2.0;
  for (const auto& b : run.blocks) {
    orbits.push_back(b.orbits), phases.push_back(b.phase);
    double& half = b.orbits <= middle ? first_half : second_half;
    half = std::max(half, b.energy_error);
  }
  LongRunVerdict v{fit_line(orbits, phases), 0, std::max(first_half, second_half), false, {}};
  v.residual = largest_residual(v.fit, orbits, phases);
  const double drift = std::abs(v.fit.slope) * orbits.back();
  v.linear = v.residual <= 0.1 * drift;
  // Below 1e-11 the energy error is rounding, whichever half is larger.
  const bool rounding_level = v.max_energy_error < 1e-11;
  const bool bounded = rounding_level || second_half <= 2 * first_half;
  const char* energy = rounding_level ? "stays at the level of rounding" : bounded ? "stays bounded" : "grows";
  // Kepler: the orbital frequency is (-2E)^(3/2), so an energy error dE
  // (rounding, in a symplectic run) shifts it by 3 dE, and the phase by
  // 3 dE t: what the measured energy error alone allows by 1e9 orbits.
  const double energy_phase = 3 * v.max_energy_error * 2 * M_PI * kExtrapolatedOrbits;
  char text[1000];
  if (v.linear)
    std::snprintf(text, sizeof text,
                  "%d steps/orbit: the phase drifts linearly, %.3g rad per orbit (the line misses the data by at most "
                  "%.2g, %.2g%% of the drift over the run), and the energy error %s (at most %.2g). At 1e9 orbits the "
                  "phase is off by %.3g rad, a position error of %.3g%s. Trust it as far as the drift rate stays as "
                  "measured over 1e5 orbits, 1e4 times beyond the data%s; the energy error, at its measured level, "
                  "could add up to %.2g rad.",
                  run.steps_per_orbit, v.fit.slope, v.residual, 100 * v.residual / drift, energy, v.max_energy_error,
                  v.fit(kExtrapolatedOrbits), chord(v.fit(kExtrapolatedOrbits)),
                  std::abs(v.fit(kExtrapolatedOrbits)) > M_PI ? " (more than half an orbit: where on its orbit the planet is, "
                                                          "is lost)"
                                                        : "",
                  bounded ? "" : " (the growing energy error says it may not)", energy_phase);
  else
    std::snprintf(text, sizeof text,
                  "%d steps/orbit: the phase error does not drift steadily (a line misses it by %.2g, more than a tenth "
                  "of the %.2g it would drift over the run): no trend to extrapolate. Over 1e5 orbits the position "
                  "error stays below %.2g and the energy error %s (at most %.2g); at that energy error the phase could "
                  "wander by up to %.2g rad by 1e9 orbits, and these data say no more than that.",
                  run.steps_per_orbit, v.residual, drift, run.max_error, energy, v.max_energy_error, energy_phase);
  v.text = text;
  return v;
}

}  // namespace vibra
