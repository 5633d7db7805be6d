// Registers vibra analyze fd-accuracy and its options.
#include "cli/analyze/analyses.hpp"
#include "cli/analyze/analysis_output.hpp"

namespace vibra::cli {

namespace {
struct FdAccuracyOptions {
  app::FdAccuracyOptions experiment;
  AnalysisOutput output;
};

void run(const FdAccuracyOptions& o) {
  check_output(o.output);
  show(o.output, app::fd_accuracy_experiment(o.experiment));
}
}  // namespace

void add_fd_accuracy_analysis(CLI::App& analyze) {
  auto o = std::make_shared<FdAccuracyOptions>();
  CLI::App* cmd = analyze.add_subcommand(
      "fd-accuracy", "How well [DtDt u] approximates u'': E(p) = 4 sin^2(p/2)/p^2 and its Taylor polynomial (Exercise 1.8)");
  cmd->add_option("--points", o->experiment.points, "Values of p = w dt, evenly from 0 to pi")->capture_default_str();
  add_output_options(*cmd, o->output);
  cmd->footer("Example (Exercise 1.8):\n  vibra analyze fd-accuracy -o fd_accuracy.png\n");
  cmd->callback([o] { run(*o); });
}

}  // namespace vibra::cli
