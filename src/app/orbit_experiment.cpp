#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "app/experiments.hpp"
#include "app/list_option.hpp"
#include "core/analysis/orbit_error.hpp"
#include "core/analysis/power_law_fit.hpp"
#include "core/error.hpp"
#include "render/stop_signal.hpp"
#include "scenes/analysis_figures.hpp"

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
  std::vector<PowerLaw> fits;
  if (o.long_run) {
    Table growth({"steps_per_orbit", "orbits", "max_error", "growth_exponent", "error_at_1e9_orbits", "cpu_s",
                  "cpu_s_for_1e9_orbits"});
    for (int n : steps) {
      OrbitProgress progress(n);
      long_runs.push_back(circular_orbit_run("pefrl", n, kLongOrbits, kBlockOrbits, std::ref(progress)));
      const OrbitRun& run = long_runs.back();
      std::vector<double> orbits, errors;
      for (const auto& b : run.blocks) orbits.push_back(b.orbits), errors.push_back(b.max_error);
      fits.push_back(fit_power_law(orbits, errors));
      growth.add_row({static_cast<long long>(n), run.blocks.back().orbits, run.max_error, fits.back().exponent,
                      std::min(fits.back()(kTargetOrbits), kOrbitDiameter), run.cpu_seconds,
                      run.cpu_seconds * kTargetOrbits / kLongOrbits});
    }
    result.tables.push_back(
        {"PEFRL over 100000 orbits: max error per block of 1000 orbits fitted by c n^p (least squares on logs), "
         "extrapolated to 1e9 orbits and capped at 2, the orbit's diameter (an error of 2 means the phase is lost)",
         std::move(growth)});
  }
  result.figure = [runs = std::move(runs), long_runs = std::move(long_runs), fits = std::move(fits),
                   title = "Circular orbit of two-body, scheme " + o.scheme](int w, int h) {
    return scenes::orbit_figure(runs, long_runs, fits, title, w, h);
  };
  return result;
}

}  // namespace vibra::app
