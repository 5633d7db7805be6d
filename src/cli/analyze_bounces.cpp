#include <cstdio>

#include "cli/analyses.hpp"
#include "cli/analysis_output.hpp"
#include "cli/model_help.hpp"
#include "core/event_trajectory.hpp"
#include "core/models/model.hpp"

namespace vibra::cli {

namespace {
struct BouncesOptions {
  std::vector<std::string> settings;
  AnalysisOutput output;
};

void run(const BouncesOptions& o) {
  const Parameters p = model_settings("bouncing-ball", o.settings);
  auto trajectory = find_model("bouncing-ball").build(p);
  auto& events = dynamic_cast<EventTrajectory&>(*trajectory);
  const double g = p.number("g");
  Table table({"n", "t", "v_before", "v_after", "h_apex"});
  long long n = 0;
  // The apex after an impact is where the rebound speed v is spent on height: v^2/(2g).
  events.on_event([&](const EventTrajectory::Event& e) {
    table.add_row({++n, e.t, e.v_before, e.v_after, e.v_after * e.v_after / (2 * g)});
  });
  while (trajectory->advance()) {
  }
  print_table(o.output,
              "Impacts of bouncing-ball (" + std::string(scheme_info(trajectory->info().mesh.scheme).name) +
                  "), located inside the step; h_apex is the apex height after the impact",
              table);
}
}  // namespace

void add_bounces_analysis(CLI::App& analyze) {
  auto o = std::make_shared<BouncesOptions>();
  CLI::App* cmd = analyze.add_subcommand("bounces", "Every impact of the bouncing ball: time, speeds, next apex (Exercise 1.24)");
  cmd->add_option("--set", o->settings, "KEY=VALUE bouncing-ball setting, repeatable (vibra solve bouncing-ball --help)")
      ->allow_extra_args(false);
  cmd->add_flag("--csv", o->output.csv, "Print the table as CSV");
  cmd->footer("Example:\n  vibra analyze bounces --set C_R=0.5 --set periods=4 --csv\n");
  cmd->callback([o] { run(*o); });
}

}  // namespace vibra::cli
