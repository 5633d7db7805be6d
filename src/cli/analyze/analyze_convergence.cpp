// Registers vibra analyze convergence and its options.
#include "cli/analyze/analyses.hpp"
#include "cli/analyze/analysis_output.hpp"
#include "cli/option_checks.hpp"

namespace vibra::cli {

namespace {
struct ConvergenceOptions {
  app::ConvergenceOptions experiment;
  AnalysisOutput output;
};

void run(const ConvergenceOptions& o) {
  check_output(o.output);
  show(o.output, app::convergence_experiment(o.experiment));
}
}  // namespace

void add_convergence_analysis(CLI::App& analyze) {
  auto o = std::make_shared<ConvergenceOptions>();
  CLI::App* cmd = analyze.add_subcommand("convergence", "Errors and convergence rates for halved dt against the exact solution");
  cmd->add_option("MODEL", o->experiment.model, "A model with an exact solution: undamped, vibration, rlc, resonance, sliding-box or two-body (the error says which settings)");
  cmd->add_option("--set", o->experiment.settings, "KEY=VALUE model setting, repeatable; dt (or steps_per_period) is the first level's")
      ->allow_extra_args(false);
  cmd->add_option("--levels", o->experiment.levels,
                  "Number of dt values, each half the one before (default: halve until the last two rates agree "
                  "within 0.05, 4 to 14 levels)")
      ->check(ranged("--levels"));
  cmd->add_option("--compare", o->experiment.compare,
                  "scheme=A,B,...: a study per scheme, one table and one log-log figure with a line per scheme");
  add_output_options(*cmd, o->output);
  cmd->footer("Examples:\n  vibra analyze convergence undamped --set scheme=rk4 --set T=4 --levels 6 -o convergence_rk4.png\n"
              "  vibra analyze convergence undamped --compare scheme=centered,centered-adjusted -o figure_1_1.png\n");
  cmd->callback([o] { run(*o); });
}

}  // namespace vibra::cli
