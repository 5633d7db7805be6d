// Registers vibra analyze frequency and its options.
#include "cli/analyze/analyses.hpp"
#include "cli/analyze/analysis_output.hpp"

namespace vibra::cli {

namespace {
struct FrequencyOptions {
  app::FrequencyOptions experiment;
  AnalysisOutput output;
};

void run(const FrequencyOptions& o) {
  check_output(o.output);
  show(o.output, app::frequency_experiment(o.experiment));
}
}  // namespace

void add_frequency_analysis(CLI::App& analyze) {
  auto o = std::make_shared<FrequencyOptions>();
  CLI::App* cmd = analyze.add_subcommand("frequency", "The centered scheme's numerical frequency (1.18) and its series (1.19)");
  cmd->add_option("--w", o->experiment.w, "Angular frequency w of u'' + w^2 u = 0")->capture_default_str();
  cmd->add_option("--steps-per-period", o->experiment.steps_per_period,
                  "Comma-separated steps per period N_P (>= pi), dt = 2 pi/(w N_P)")
      ->capture_default_str();
  add_output_options(*cmd, o->output);
  cmd->footer("Example (the book's Figure 1.4):\n  vibra analyze frequency --w 1 -o frequency.png\n");
  cmd->callback([o] { run(*o); });
}

}  // namespace vibra::cli
