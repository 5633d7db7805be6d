// vibra analyze orbit: the two-body orbit's radius and phase errors over blocks of orbits.
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "jobs/experiments/experiments.hpp"
#include "jobs/list_option.hpp"
#include "core/analysis/line_fit.hpp"
#include "core/analysis/orbit_error.hpp"
#include "core/error.hpp"
#include "render/output/stop_signal.hpp"
#include "scenes/figures/analysis_figures.hpp"

namespace vibra::app {

namespace {
constexpr long long kLongOrbits = 100'000, kBlockOrbits = 1'000;
constexpr double kTargetOrbits = 1e9;
// Two points on the unit circle are never further apart than this.
constexpr double kOrbitDiameter = 2.0;

/// Progress of a long run on stderr: one updating line on a terminal, a line
/// every 10 s otherwise (logs).
class OrbitProgress {
 public:
  explicit OrbitProgress(int steps_per_orbit) : steps_per_orbit_(steps_per_orbit) {}
  void operator()(long long orbits) {
    render::throw_if_stop_requested();
    const auto now = std::chrono::steady_clock::now();
    if (orbits < kLongOrbits && now - last_ < (terminal_ ? std::chrono::milliseconds(200) : std::chrono::seconds(10))) return;
    last_ = now;
    const double elapsed = std::chrono::duration<double>(now - start_).count();
    const double eta = elapsed * (kLongOrbits - orbits) / std::max(1LL, orbits);
    std::fprintf(stderr, "%sorbit --long: pefrl, %d steps/orbit: %lld/%lld orbits, ETA %.0f s%s", terminal_ ? "\r" : "",
                 steps_per_orbit_, orbits, kLongOrbits, eta, terminal_ && orbits < kLongOrbits ? "" : "\n");
    std::fflush(stderr);
  }

 private:
  int steps_per_orbit_;
  bool terminal_ = isatty(STDERR_FILENO) == 1;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now(), last_ = start_;
};

/// The distance between two points of the unit circle `phase` apart.
double chord(double phase) { return std::min(kOrbitDiameter, std::abs(2 * std::sin(phase / 2))); }

/// What a long run's data support: a linear phase drift (the line explains
/// the phase errors to within a tenth of the drift it fits over the run) to
/// extrapolate, and a bounded energy error (the second half's largest at
/// most twice the first half's), in a sentence that says how far to trust it.
struct LongRunVerdict {
  Line fit;
  double residual, max_energy_error;
  bool linear;
  std::string text;
};
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
  const double energy_phase = 3 * v.max_energy_error * 2 * M_PI * kTargetOrbits;
  char text[1000];
  if (v.linear)
    std::snprintf(text, sizeof text,
                  "%d steps/orbit: the phase drifts linearly, %.3g rad per orbit (the line misses the data by at most "
                  "%.2g, %.2g%% of the drift over the run), and the energy error %s (at most %.2g). At 1e9 orbits the "
                  "phase is off by %.3g rad, a position error of %.3g%s. Trust it as far as the drift rate stays as "
                  "measured over 1e5 orbits, 1e4 times beyond the data%s; the energy error, at its measured level, "
                  "could add up to %.2g rad.",
                  run.steps_per_orbit, v.fit.slope, v.residual, 100 * v.residual / drift, energy, v.max_energy_error,
                  v.fit(kTargetOrbits), chord(v.fit(kTargetOrbits)),
                  std::abs(v.fit(kTargetOrbits)) > M_PI ? " (more than half an orbit: where on its orbit the planet is, "
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

std::vector<int> whole_numbers(const std::string& option, const std::string& text) {
  std::vector<int> out;
  for (double x : positive_list(option, text)) {
    if (x != std::round(x) || x > 1e8) throw UsageError(option + " takes whole numbers up to 1e8, e.g. 200,400");
    out.push_back(static_cast<int>(x));
  }
  return out;
}
}  // namespace

ExperimentResult orbit_experiment(const OrbitOptions& o) {
  if (o.orbits < 1) throw UsageError("--orbits must be >= 1, e.g. --orbits 100");
  const std::vector<int> steps = whole_numbers("--steps-per-orbit", o.steps_per_orbit);
  std::vector<OrbitRun> runs;
  Table table({"scheme", "steps_per_orbit", "dt", "orbits", "max_error", "cpu_s"});
  for (int n : steps) {
    runs.push_back(circular_orbit_run(o.scheme, n, o.orbits, o.orbits));
    table.add_row({o.scheme, static_cast<long long>(n), runs.back().dt, o.orbits, runs.back().max_error, runs.back().cpu_seconds});
  }
  ExperimentResult result;
  result.tables.push_back(
      {"Circular orbit x = cos t, y = sin t of two-body: max |(x, y) - exact| over the run", std::move(table)});

  std::vector<OrbitRun> long_runs;
  std::vector<Line> fits;
  if (o.long_run) {
    Table growth({"steps_per_orbit", "orbits", "max_error", "max_energy_error", "phase_drift_per_orbit",
                  "fit_residual", "phase_at_1e9_orbits", "error_at_1e9_orbits", "cpu_s", "cpu_s_for_1e9_orbits"});
    std::string verdicts;
    for (int n : steps) {
      OrbitProgress progress(n);
      long_runs.push_back(circular_orbit_run("pefrl", n, kLongOrbits, kBlockOrbits, std::ref(progress)));
      const OrbitRun& run = long_runs.back();
      const LongRunVerdict v = judge_long_run(run);
      fits.push_back(v.fit);
      growth.add_row({static_cast<long long>(n), run.blocks.back().orbits, run.max_error, v.max_energy_error,
                      v.fit.slope, v.residual, v.linear ? Table::Cell(v.fit(kTargetOrbits)) : Table::Cell(std::string()),
                      v.linear ? Table::Cell(chord(v.fit(kTargetOrbits))) : Table::Cell(std::string()), run.cpu_seconds,
                      run.cpu_seconds * kTargetOrbits / kLongOrbits});
      verdicts += (verdicts.empty() ? "" : "\n") + v.text;
    }
    result.tables.push_back(
        {"PEFRL over 100000 orbits in blocks of 1000: the angle's error atan2(y, x) - t at each block's end fitted by a "
         "straight line (least squares), extrapolated to 1e9 orbits only where the line fits; the energy error "
         "|E - E(0)|; the position error at 1e9 orbits is the chord 2|sin(phase/2)|, at most 2 (the phase is lost)",
         std::move(growth)});
    result.conclusion = verdicts;
  }
  result.figure = [runs = std::move(runs), long_runs = std::move(long_runs), fits = std::move(fits),
                   title = "Circular orbit of two-body, scheme " + o.scheme](int w, int h) {
    return scenes::orbit_figure(runs, long_runs, fits, title, w, h);
  };
  return result;
}

}  // namespace vibra::app
