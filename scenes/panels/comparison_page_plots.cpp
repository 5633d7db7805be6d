// A lecture page's plots for a comparison: one collector per member, merged into one set of panels.
#include "scenes/panels/comparison_page_plots.hpp"

#include <algorithm>

#include "scenes/diagrams/comparison_labels.hpp"

namespace vibra::scenes {

ComparisonPagePlots::ComparisonPagePlots(const ComparisonTrajectory& runs, const render::Color& first) {
  const Comparison& comparison = runs.comparison();
  for (size_t i = 0; i < comparison.size(); ++i) {
    const TrajectoryInfo& info = comparison.trajectory(i).info();
    std::vector<std::string> panels = page_panel_names(info);
    if (comparison.same_problem() && i > 0) std::erase(panels, "exact");  // one problem: its exact solution once
    members_.emplace_back(info, panels, comparison.label(i), member_color(first, i));
    columns_.push_back(MemberColumns::of(runs, i));
    slice_.resize(std::max(slice_.size(), columns_.back().width));
  }
}

void ComparisonPagePlots::observe(const ComparisonTrajectory& runs, std::span<const double> row) {
  for (size_t i = 0; i < members_.size(); ++i) {
    if (runs.at_sample(i)) members_[i].observe(runs.comparison().trajectory(i), columns_[i].slice(row, slice_));
  }
}

std::vector<render::PagePanel> ComparisonPagePlots::take_panels() {
  std::vector<render::PagePanel> panels;
  for (auto& member : members_) merge_page_panels(panels, member.take_panels());
  return panels;
}

}  // namespace vibra::scenes
