// Registers vibra analyze bounces and its options.
#include "cli/analyze/analyses.hpp"
#include "cli/analyze/analysis_output.hpp"

namespace vibra::cli {

namespace {
struct BouncesOptions {
  app::BouncesOptions experiment;
  AnalysisOutput output;
};

void run(const BouncesOptions& o) { show(o.output, app::bounces_experiment(o.experiment)); }
}  // namespace

void add_bounces_analysis(CLI::App& analyze) {
  auto o = std::make_shared<BouncesOptions>();
  CLI::App* cmd = analyze.add_subcommand("bounces", "Every impact of the bouncing ball: time, speeds, next apex (Exercise 1.24)");
  cmd->add_option("--set", o->experiment.settings, "KEY=VALUE bouncing-ball setting, repeatable (vibra solve bouncing-ball --help)")
      ->allow_extra_args(false);
  cmd->add_flag("--csv", o->output.csv, "Print the table as CSV");
  cmd->footer("Example:\n  vibra analyze bounces --set C_R=0.5 --set periods=4 --csv\n");
  cmd->callback([o] { run(*o); });
}

}  // namespace vibra::cli
