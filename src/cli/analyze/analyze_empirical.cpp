// Registers vibra analyze empirical and its options.
#include "cli/analyze/analyses.hpp"
#include "cli/analyze/analysis_output.hpp"

namespace vibra::cli {

namespace {
struct EmpiricalOptions {
  app::EmpiricalOptions experiment;
  AnalysisOutput output;
};

void run(const EmpiricalOptions& o) {
  check_output(o.output);
  show(o.output, app::empirical_experiment(o.experiment));
}
}  // namespace

void add_empirical_analysis(CLI::App& analyze) {
  auto o = std::make_shared<EmpiricalOptions>();
  CLI::App* cmd = analyze.add_subcommand("empirical", "Local periods and amplitudes from the extrema of the main quantity");
  cmd->add_option("MODEL", o->experiment.model, "Model name (vibra solve --help lists them)");
  cmd->add_option("--set", o->experiment.settings, "KEY=VALUE model setting, repeatable")->allow_extra_args(false);
  cmd->add_option("--dt", o->experiment.dt, "Comma-separated time steps, one run each (default: the model's dt)");
  cmd->add_flag("--mesh-extrema", o->experiment.mesh_extrema,
                "Place extrema at mesh points as the book's code does (periods become multiples of dt)");
  add_output_options(*cmd, o->output);
  cmd->footer("Example (the book's Figure 1.3):\n"
              "  vibra analyze empirical undamped --dt 0.1,0.05,0.025 --set periods=20 -o empirical.png\n");
  cmd->callback([o] { run(*o); });
}

}  // namespace vibra::cli
