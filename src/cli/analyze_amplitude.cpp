#include <cstdio>

#include "cli/analyses.hpp"
#include "cli/analysis_output.hpp"
#include "cli/model_help.hpp"
#include "core/analysis/empirical.hpp"
#include "core/error.hpp"
#include "scenes/analysis_figures.hpp"

namespace vibra::cli {

namespace {
struct AmplitudeOptions {
  std::string schemes = "forward-euler,backward-euler,crank-nicolson,rk2,rk4";
  std::string dt = "0.025";
  std::string periods = "10";
  AnalysisOutput output;
};

void run(const AmplitudeOptions& o) {
  check_output(o.output);
  const double I = 1;
  Table table({"scheme", "i", "t", "amplitude", "amplitude_error"});
  std::vector<scenes::LabelledCycles> runs;
  for (const auto& scheme : word_list("--schemes", o.schemes)) {
    const Parameters p = model_settings("undamped", {"scheme=" + scheme, "dt=" + o.dt, "periods=" + o.periods, "I=1", "V=0"});
    auto trajectory = find_model("undamped").build(p);
    auto cycles = oscillation_cycles(*trajectory);
    if (cycles.empty()) throw UsageError("no complete oscillation with --periods " + o.periods + ": give at least 2 periods");
    for (const auto& c : cycles) table.add_row({scheme, static_cast<long long>(c.i), c.t, c.amplitude, c.amplitude - I});
    runs.push_back({scheme, std::move(cycles)});
  }
  const std::string what = "u'' + (2 pi)^2 u = 0, u(0) = 1, u'(0) = 0, dt = " + o.dt;
  print_table(o.output, "Empirical amplitudes a_i (exact: 1) of " + what, table);
  write_figure(o.output, [&](int w, int h) {
    return scenes::amplitude_figure(runs, I, "Amplitude of <i>u</i>'' + (2π)<sup>2</sup><i>u</i> = 0, Δ<i>t</i> = " + o.dt, w, h);
  });
}
}  // namespace

void add_amplitude_analysis(CLI::App& analyze) {
  auto o = std::make_shared<AmplitudeOptions>();
  CLI::App* cmd = analyze.add_subcommand(
      "amplitude", "Amplitude errors of first-order-system solvers on the undamped oscillator (Exercise 1.13)");
  cmd->add_option("--schemes", o->schemes, "Comma-separated schemes")->capture_default_str();
  cmd->add_option("--dt", o->dt, "Time step (the period is 1)")->capture_default_str();
  cmd->add_option("--periods", o->periods, "Number of periods")->capture_default_str();
  add_output_options(*cmd, o->output);
  cmd->footer("Example:\n  vibra analyze amplitude --schemes rk2,rk4,crank-nicolson --periods 40 -o amplitude.png\n");
  cmd->callback([o] { run(*o); });
}

}  // namespace vibra::cli
