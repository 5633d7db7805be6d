#include <cstdio>

#include "cli/analyses.hpp"
#include "cli/analysis_output.hpp"
#include "core/analysis/resonance.hpp"
#include "scenes/resonance_figure.hpp"

namespace vibra::cli {

namespace {
struct ResonanceOptions {
  std::string beta = "0.005,0.05,0.2";
  std::string gamma = "5,1.5,1.1,1";
  AnalysisOutput output;
};

void run(const ResonanceOptions& o) {
  check_output(o.output);
  const std::vector<double> betas = positive_list("--beta", o.beta), gammas = positive_list("--gamma", o.gamma);
  std::vector<ResonancePoint> points;
  Table table({"beta", "gamma", "amplitude", "exact"});
  for (double beta : betas)
    for (double gamma : gammas) {
      points.push_back(measure_steady_amplitude(beta, gamma));
      table.add_row({beta, gamma, points.back().amplitude, points.back().exact});
    }
  print_table(o.output,
              "Steady amplitude of u'' + beta u' + u = sin(gamma t) after the transient (RK4), against "
              "1/sqrt((1 - gamma^2)^2 + (beta gamma)^2)",
              table);
  write_figure(o.output, [&](int width, int height) { return scenes::resonance_figure(points, width, height); });
}
}  // namespace

void add_resonance_analysis(CLI::App& analyze) {
  auto o = std::make_shared<ResonanceOptions>();
  CLI::App* cmd = analyze.add_subcommand(
      "resonance", "Steady amplitude of the forced vibration u'' + beta u' + u = sin(gamma t) (Exercise 1.22)");
  cmd->add_option("--beta", o->beta, "Comma-separated damping values beta > 0")->capture_default_str();
  cmd->add_option("--gamma", o->gamma, "Comma-separated forcing frequencies gamma > 0 (in units of the natural one)")
      ->capture_default_str();
  add_output_options(*cmd, o->output);
  cmd->footer("Example (Exercise 1.22):\n  vibra analyze resonance -o resonance.png\n");
  cmd->callback([o] { run(*o); });
}

}  // namespace vibra::cli
