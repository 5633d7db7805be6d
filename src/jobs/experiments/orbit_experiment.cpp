// vibra analyze orbit: the two-body orbit's radius and phase errors over blocks of orbits.
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "jobs/experiments/experiments.hpp"
#include "jobs/list_option.hpp"
#include "core/analysis/line_fit.hpp"
#include "core/analysis/long_run_verdict.hpp"
#include "core/analysis/orbit_error.hpp"
#include "core/error.hpp"
#include "render/output/stop_signal.hpp"
#include "scenes/figures/analysis_figures.hpp"

namespace vibra::app {

namespace {
constexpr long long kLongOrbits = 100'000, kBlockOrbits = 1'000;

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
                      v.fit.slope, v.residual, v.linear ? Table::Cell(v.fit(kExtrapolatedOrbits)) : Table::Cell(std::string()),
                      v.linear ? Table::Cell(chord(v.fit(kExtrapolatedOrbits))) : Table::Cell(std::string()), run.cpu_seconds,
                      run.cpu_seconds * kExtrapolatedOrbits / kLongOrbits});
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
