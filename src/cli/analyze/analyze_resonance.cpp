// Registers vibra analyze resonance and its options.
#include "cli/analyze/analyses.hpp"
#include "cli/analyze/analysis_output.hpp"

namespace vibra::cli {

namespace {
struct ResonanceOptions {
  app::ResonanceOptions experiment;
  AnalysisOutput output;
};

void run(const ResonanceOptions& o) {
  check_output(o.output);
  show(o.output, app::resonance_experiment(o.experiment));
}
}  // namespace

void add_resonance_analysis(CLI::App& analyze) {
  auto o = std::make_shared<ResonanceOptions>();
  CLI::App* cmd = analyze.add_subcommand(
      "resonance", "Steady amplitude of the forced vibration u'' + beta u' + u = sin(gamma t) (Exercise 1.22)");
  cmd->add_option("--beta", o->experiment.beta, "Comma-separated damping values beta > 0")->capture_default_str();
  cmd->add_option("--gamma", o->experiment.gamma, "Comma-separated forcing frequencies gamma > 0 (in units of the natural one)")
      ->capture_default_str();
  add_output_options(*cmd, o->output);
  cmd->footer("Example (Exercise 1.22):\n  vibra analyze resonance -o resonance.png\n");
  cmd->callback([o] { run(*o); });
}

}  // namespace vibra::cli
