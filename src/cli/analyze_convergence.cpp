#include <cmath>
#include <cstdio>
#include <optional>

#include "cli/analyses.hpp"
#include "cli/analysis_output.hpp"
#include "core/analysis/model_convergence.hpp"
#include "core/error.hpp"
#include "scenes/analysis_figures.hpp"

namespace vibra::cli {

namespace {
struct ConvergenceOptions {
  std::string model;
  std::vector<std::string> settings;
  std::optional<int> levels;  ///< none: halve dt until the rates settle
  AnalysisOutput output;
};

/// Says plainly whether the last rates mean the order: on stdout under the
/// table, or on stderr with --csv so the CSV stays a table (not with --quiet).
void say_whether_settled(const AnalysisOutput& output, const ModelConvergence& study) {
  const auto& levels = study.levels;
  char text[320];
  if (study.settled)
    std::snprintf(text, sizeof text, "The rates have settled: r = %.2f over the last two levels (order %d).",
                  levels.back().rate, study.order);
  else if (levels.size() < 3)
    std::snprintf(text, sizeof text, "One rate cannot show whether the rates have settled: use 3 or more --levels.");
  else
    std::snprintf(text, sizeof text,
                  "The rates have NOT settled: the last two differ by %.2f (more than %.2f), so r is not yet the order; "
                  "use more --levels or a smaller dt.",
                  std::abs(levels.back().rate - levels[levels.size() - 2].rate), kSettledRateTolerance);
  if (output.csv && output.quiet) return;
  std::FILE* stream = output.csv ? stderr : stdout;
  std::fprintf(stream, "%s%s\n", output.csv ? "vibra: " : "", text);
  std::fflush(stream);
}

void run(const ConvergenceOptions& o) {
  if (o.model.empty())
    throw UsageError("vibra analyze convergence needs a MODEL, e.g. vibra analyze convergence undamped --set scheme=rk4");
  check_output(o.output);
  if (o.levels && (*o.levels < 2 || *o.levels > 20))
    throw UsageError("--levels must be 2..20 (each level halves dt), e.g. --levels 5");
  const ModelConvergence study = model_convergence(o.model, o.settings, o.levels.value_or(0));
  Table table({"i", "dt", "E", "r"});
  for (size_t i = 0; i < study.levels.size(); ++i) {
    const ConvergenceLevel& level = study.levels[i];
    table.add_row({static_cast<long long>(i), level.dt, level.error, level.rate});
  }
  const std::string what = o.model + ", scheme " + study.scheme + " (order " + std::to_string(study.order) + ")";
  print_table(o.output, "Convergence of " + what + ": E = sqrt(dt sum (u^n - u_e(t_n))^2), r = ln(E_{i-1}/E_i) / ln 2",
              table);
  say_whether_settled(o.output, study);
  write_figure(o.output, [&](int w, int h) { return scenes::convergence_figure(study, "Convergence of " + what, w, h); });
}
}  // namespace

void add_convergence_analysis(CLI::App& analyze) {
  auto o = std::make_shared<ConvergenceOptions>();
  CLI::App* cmd = analyze.add_subcommand("convergence", "Errors and convergence rates for halved dt against the exact solution");
  cmd->add_option("MODEL", o->model, "A model with an exact solution: undamped, or two-body with a circular orbit");
  cmd->add_option("--set", o->settings, "KEY=VALUE model setting, repeatable; dt (or steps_per_period) is the first level's")
      ->allow_extra_args(false);
  cmd->add_option("--levels", o->levels,
                  "Number of dt values, each half the one before (default: halve until the last two rates agree "
                  "within 0.05, 4 to 14 levels)");
  add_output_options(*cmd, o->output);
  cmd->footer("Example:\n  vibra analyze convergence undamped --set scheme=rk4 --set T=4 --levels 6 -o convergence_rk4.png\n");
  cmd->callback([o] { run(*o); });
}

}  // namespace vibra::cli
