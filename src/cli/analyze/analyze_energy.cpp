// Registers vibra analyze energy and its options.
#include "cli/analyze/analyses.hpp"
#include "cli/analyze/analysis_output.hpp"

namespace vibra::cli {

namespace {
struct EnergyOptions {
  app::EnergyOptions experiment;
  AnalysisOutput output;
};

void run(const EnergyOptions& o) {
  check_output(o.output);
  show(o.output, app::energy_experiment(o.experiment));
}
}  // namespace

void add_energy_analysis(CLI::App& analyze) {
  auto o = std::make_shared<EnergyOptions>();
  CLI::App* cmd = analyze.add_subcommand("energy", "The chapter's energy-error table: max |e_E|/E(0) per scheme, T and dt");
  cmd->add_option("--schemes", o->experiment.schemes, "Comma-separated schemes")->capture_default_str();
  cmd->add_option("--T", o->experiment.T, "Comma-separated end times")->capture_default_str();
  cmd->add_option("--dt", o->experiment.dt, "Comma-separated time steps")->capture_default_str();
  cmd->add_flag("--rates", o->experiment.rates,
                "Add the energy error's convergence rate between successive dt (Exercise 1.9)");
  add_output_options(*cmd, o->output);
  cmd->footer("Example:\n  vibra analyze energy --schemes rk4,euler-cromer --T 10 --dt 0.05,0.025 -o energy.png\n");
  cmd->callback([o] { run(*o); });
}

}  // namespace vibra::cli
