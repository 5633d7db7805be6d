// Registers vibra analyze amplitude and its options.
#include "cli/analyze/analyses.hpp"
#include "cli/analyze/analysis_output.hpp"

namespace vibra::cli {

namespace {
struct AmplitudeOptions {
  app::AmplitudeOptions experiment;
  AnalysisOutput output;
};

void run(const AmplitudeOptions& o) {
  check_output(o.output);
  show(o.output, app::amplitude_experiment(o.experiment));
}
}  // namespace

void add_amplitude_analysis(CLI::App& analyze) {
  auto o = std::make_shared<AmplitudeOptions>();
  CLI::App* cmd = analyze.add_subcommand(
      "amplitude", "Amplitude errors of first-order-system solvers on the undamped oscillator (Exercise 1.13)");
  cmd->add_option("--schemes", o->experiment.schemes, "Comma-separated schemes")->capture_default_str();
  cmd->add_option("--dt", o->experiment.dt, "Time step (the period is 1)")->capture_default_str();
  cmd->add_option("--periods", o->experiment.periods, "Number of periods")->capture_default_str();
  add_output_options(*cmd, o->output);
  cmd->footer("Example:\n  vibra analyze amplitude --schemes rk2,rk4,crank-nicolson --periods 40 -o amplitude.png\n");
  cmd->callback([o] { run(*o); });
}

}  // namespace vibra::cli
