#include <cmath>
#include <cstdio>

#include "cli/analyses.hpp"
#include "cli/analysis_output.hpp"
#include "core/analysis/numerical_frequency.hpp"
#include "core/error.hpp"
#include "core/expression.hpp"
#include "scenes/analysis_figures.hpp"

namespace vibra::cli {

namespace {
struct FrequencyOptions {
  std::string w = "1";
  std::string steps_per_period = "80,60,40,30,20,15,10,8,6,5,4";
  AnalysisOutput output;
};

void run(const FrequencyOptions& o) {
  check_output(o.output);
  const double w = evaluate_constant("--w", o.w);
  if (!(w > 0) || !std::isfinite(w)) throw UsageError("--w must be a positive number, e.g. --w 1");
  std::vector<double> steps = positive_list("--steps-per-period", o.steps_per_period);
  for (double n : steps)
    if (n < M_PI)
      throw UsageError("--steps-per-period " + std::to_string(n) +
                       " is below pi, the stability limit (dt = 2/w): give values >= 3.1416");
  steps.push_back(M_PI);  // the stability limit dt = 2/w
  Table table({"dt", "steps_per_period", "w_tilde", "w_series", "w_tilde_rel_error", "w_series_rel_error"});
  for (double n : steps) {
    const double dt = n == M_PI ? 2 / w : 2 * M_PI / (w * n);
    const double exact = numerical_frequency(w, dt), series = numerical_frequency_series(w, dt);
    table.add_row({dt, n, exact, series, exact / w - 1, series / w - 1});
  }
  char heading[160];
  std::snprintf(heading, sizeof heading,
                "Centered scheme's frequency w~ = (2/dt) asin(w dt/2) (1.18) and series w (1 + w^2 dt^2/24) (1.19), "
                "w = %g; last row: the stability limit dt = 2/w",
                w);
  print_table(o.output, heading, table);
  write_figure(o.output, [&](int width, int height) { return scenes::frequency_figure(w, width, height); });
}
}  // namespace

void add_frequency_analysis(CLI::App& analyze) {
  auto o = std::make_shared<FrequencyOptions>();
  CLI::App* cmd = analyze.add_subcommand("frequency", "The centered scheme's numerical frequency (1.18) and its series (1.19)");
  cmd->add_option("--w", o->w, "Angular frequency w of u'' + w^2 u = 0")->capture_default_str();
  cmd->add_option("--steps-per-period", o->steps_per_period,
                  "Comma-separated steps per period N_P (>= pi), dt = 2 pi/(w N_P)")
      ->capture_default_str();
  add_output_options(*cmd, o->output);
  cmd->footer("Example (the book's Figure 1.4):\n  vibra analyze frequency --w 1 -o frequency.png\n");
  cmd->callback([o] { run(*o); });
}

}  // namespace vibra::cli
