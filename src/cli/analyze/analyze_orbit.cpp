// Registers vibra analyze orbit and its options.
#include "cli/analyze/analyses.hpp"
#include "cli/analyze/analysis_output.hpp"
#include "cli/option_checks.hpp"

namespace vibra::cli {

namespace {
struct OrbitOptions {
  app::OrbitOptions experiment;
  AnalysisOutput output;
};

void run(const OrbitOptions& o) {
  check_output(o.output);
  show(o.output, app::orbit_experiment(o.experiment));
}
}  // namespace

void add_orbit_analysis(CLI::App& analyze) {
  auto o = std::make_shared<OrbitOptions>();
  CLI::App* cmd = analyze.add_subcommand("orbit", "Position error and CPU time of the circular orbit (Exercise 1.28)");
  cmd->add_option("--scheme", o->experiment.scheme, "Scheme, e.g. pefrl, rk4, euler-cromer")->capture_default_str();
  cmd->add_option("--steps-per-orbit", o->experiment.steps_per_orbit, "Comma-separated steps per orbit")->capture_default_str();
  cmd->add_option("--orbits", o->experiment.orbits, "Orbits per run")->capture_default_str()->check(ranged("--orbits"));
  cmd->add_flag("--long", o->experiment.long_run,
                "Also run PEFRL for 100000 orbits per steps-per-orbit value, fit the error growth and extrapolate "
                "error and CPU time to 1e9 orbits (a second table follows the first after a blank line)");
  add_output_options(*cmd, o->output);
  cmd->footer("Examples:\n  vibra analyze orbit --scheme rk4 --orbits 100\n"
              "  vibra analyze orbit --long --steps-per-orbit 200,400 -o orbit.png\n");
  cmd->callback([o] { run(*o); });
}

}  // namespace vibra::cli
