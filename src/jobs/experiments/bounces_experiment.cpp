// vibra analyze bounces: the bouncing ball's impacts and apex heights against the exact ones.
#include "jobs/experiments/experiments.hpp"
#include "core/event_trajectory.hpp"
#include "core/models/model.hpp"

namespace vibra::app {

ExperimentResult bounces_experiment(const BouncesOptions& o) {
  const Parameters p = model_settings("bouncing-ball", o.settings);
  auto trajectory = find_model("bouncing-ball").build(p);
  auto& events = dynamic_cast<EventTrajectory&>(*trajectory);
  const double g = p.number("g");
  Table table({"n", "t", "v_before", "v_after", "h_apex"});
  long long n = 0;
  // The apex after an impact is where the rebound speed v is spent on height: v^2/(2g).
  events.on_event([&](const EventTrajectory::Event& e) {
    if (e.t > 0) table.add_row({++n, e.t, e.v_before, e.v_after, e.v_after * e.v_after / (2 * g)});
  });
  while (trajectory->advance()) {
  }
  ExperimentResult result;
  result.tables.push_back({"Impacts of bouncing-ball (" + std::string(scheme_info(trajectory->info().mesh.scheme).name) +
                               "), located inside the step; h_apex is the apex height after the impact",
                           std::move(table)});
  return result;
}

}  // namespace vibra::app
