// A lecture page's plots for a comparison: one collector per member, merged into one set of panels.
#pragma once
#include <span>
#include <vector>

#include "core/comparison_trajectory.hpp"
#include "render/draw/color.hpp"
#include "scenes/overlays/member_columns.hpp"
#include "scenes/panels/page_plot_collector.hpp"

namespace vibra::scenes {

/// A lecture page's panels for a comparison: one collector per member, fed
/// that member's own samples (a page plots each run on its own mesh), merged
/// so that each quantity's panel holds every member's curve in the member's
/// colour, and the exact solution once where the members solve one problem.
class ComparisonPagePlots {
 public:
  /// `first` is the first member's colour (the scene's body colour).
  ComparisonPagePlots(const ComparisonTrajectory&, const render::Color& first);

  /// The comparison's current row: `runs` must be at that row.
  void observe(const ComparisonTrajectory& runs, std::span<const double> row);

  /// The merged panels; the collectors are spent.
  std::vector<render::PagePanel> take_panels();

 private:
  std::vector<PagePlotCollector> members_;
  std::vector<MemberColumns> columns_;
  std::vector<double> slice_;
};

}  // namespace vibra::scenes
