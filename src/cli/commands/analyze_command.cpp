// Registers vibra analyze: one subcommand per experiment, a misspelt experiment named and corrected.
#include <memory>

#include "cli/analyze/analyses.hpp"
#include "cli/commands.hpp"
#include "core/error.hpp"
#include "core/input/parameters.hpp"

namespace vibra::cli {

void add_analyze_command(CLI::App& app) {
  CLI::App* cmd = app.add_subcommand("analyze", "Run the chapter's experiments: tables on stdout, figures with -o");
  add_convergence_analysis(*cmd);
  add_energy_analysis(*cmd);
  add_empirical_analysis(*cmd);
  add_frequency_analysis(*cmd);
  add_fd_accuracy_analysis(*cmd);
  add_amplitude_analysis(*cmd);
  add_orbit_analysis(*cmd);
  add_resonance_analysis(*cmd);
  add_period_analysis(*cmd);
  add_bounces_analysis(*cmd);
  // Our own check instead of require_subcommand, so a misspelt experiment is named and corrected.
  auto unknown = std::make_shared<std::string>();
  cmd->add_option("EXPERIMENT", *unknown,
                  "convergence, energy, empirical, frequency, fd-accuracy, amplitude, orbit, resonance, period or bounces");
  cmd->callback([cmd, unknown] {
    if (!cmd->get_subcommands().empty()) return;
    std::vector<std::string> names;
    std::string list;
    for (const CLI::App* sub : cmd->get_subcommands({})) {
      names.push_back(sub->get_name());
      list += (list.empty() ? "" : ", ") + sub->get_name();
    }
    if (unknown->empty()) throw UsageError("vibra analyze needs an experiment: one of " + list);
    const std::string near = closest_match(*unknown, names);
    throw UsageError("unknown experiment '" + *unknown + "'" + (near.empty() ? "" : " (did you mean '" + near + "'?)") +
                     ": choose one of " + list);
  });
  cmd->footer(
      "Examples:\n"
      "  vibra analyze convergence undamped --set scheme=rk4 -o convergence.png\n"
      "  vibra analyze energy --csv\n"
      "  vibra analyze empirical undamped --dt 0.1,0.05,0.025 --set periods=20 -o figure_1_3.png\n"
      "  vibra analyze frequency -o figure_1_4.png\n"
      "  vibra analyze fd-accuracy --csv\n"
      "  vibra analyze amplitude -o amplitudes.png\n"
      "  vibra analyze orbit --scheme pefrl --orbits 100\n"
      "  vibra analyze period pendulum --set alpha=0 --set Theta=60 --csv\n"
      "  vibra analyze bounces --set C_R=0.5 --csv\n"
      "vibra analyze EXPERIMENT --help shows an experiment's options.\n");
}

}  // namespace vibra::cli
