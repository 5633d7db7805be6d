#include "cli/analyses.hpp"
#include "cli/analysis_output.hpp"
#include "core/analysis/energy_study.hpp"
#include "scenes/analysis_figures.hpp"

namespace vibra::cli {

namespace {
struct EnergyOptions {
  std::string schemes = "forward-euler,backward-euler,crank-nicolson,rk2,rk4,euler-cromer";
  std::string T = "1,10";
  std::string dt = "0.05,0.025,0.0125";
  AnalysisOutput output;
};

void run(const EnergyOptions& o) {
  check_output(o.output);
  const auto entries = energy_error_table(word_list("--schemes", o.schemes), positive_list("--T", o.T),
                                          positive_list("--dt", o.dt));
  Table table({"scheme", "T", "dt", "max_rel_energy_error"});
  for (const auto& e : entries) table.add_row({e.scheme, e.T, e.dt, e.max_relative_error});
  print_table(o.output,
              "max |e_E^n| / E(0), n = 1..Nt-1, for u'' + (2 pi)^2 u = 0, u(0) = 1, u'(0) = 0 "
              "(u' by centered differences, as the book's table)",
              table);
  write_figure(o.output, [&](int w, int h) { return scenes::energy_figure(entries, w, h); });
}
}  // namespace

void add_energy_analysis(CLI::App& analyze) {
  auto o = std::make_shared<EnergyOptions>();
  CLI::App* cmd = analyze.add_subcommand("energy", "The chapter's energy-error table: max |e_E|/E(0) per scheme, T and dt");
  cmd->add_option("--schemes", o->schemes, "Comma-separated schemes")->capture_default_str();
  cmd->add_option("--T", o->T, "Comma-separated end times")->capture_default_str();
  cmd->add_option("--dt", o->dt, "Comma-separated time steps")->capture_default_str();
  add_output_options(*cmd, o->output);
  cmd->footer("Example:\n  vibra analyze energy --schemes rk4,euler-cromer --T 10 --dt 0.05,0.025 -o energy.png\n");
  cmd->callback([o] { run(*o); });
}

}  // namespace vibra::cli
