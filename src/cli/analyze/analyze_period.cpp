// Registers vibra analyze period and its options.
#include "cli/analyze/analyses.hpp"
#include "cli/analyze/analysis_output.hpp"

namespace vibra::cli {

namespace {
struct PeriodOptions {
  app::PeriodOptions experiment;
  AnalysisOutput output;
};

void run(const PeriodOptions& o) {
  check_output(o.output);
  show(o.output, app::period_experiment(o.experiment));
}
}  // namespace

void add_period_analysis(CLI::App& analyze) {
  auto o = std::make_shared<PeriodOptions>();
  CLI::App* cmd = analyze.add_subcommand(
      "period", "Each period between upward zero crossings against the exact one; log decrement when damped");
  cmd->add_option("MODEL", o->experiment.model, "Model name (vibra solve --help lists them)");
  cmd->add_option("--set", o->experiment.settings, "KEY=VALUE model setting, repeatable")->allow_extra_args(false);
  add_output_options(*cmd, o->output);
  cmd->footer("Example (the pendulum at 60 degrees is 7% slower than 2 pi):\n"
              "  vibra analyze period pendulum --set alpha=0 --set Theta=60 -o period.png\n");
  cmd->callback([o] { run(*o); });
}

}  // namespace vibra::cli
