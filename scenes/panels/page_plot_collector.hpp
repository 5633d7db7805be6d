// Collects a run's samples into the lecture page's plots, with the panels a page shows by default.
#pragma once
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/trajectory.hpp"
#include "render/page/page_plots.hpp"

namespace vibra::scenes {

/// The panels a lecture page shows for a run by default: the scene's for the
/// pendulums (theta in degrees, S / mg and D / mg), every column but t for
/// other models, with the exact solution dashed over the main quantity where
/// it is known.
std::vector<std::string> page_panel_names(const TrajectoryInfo&);

/// Collects, from every solver row of one run, the time series of a lecture
/// page's panels, decimated as they come (render::PageSeriesData): memory is
/// bounded and no peak is lost, whatever the number of steps.
class PagePlotCollector {
 public:
  /// `panels` as for `vibra plot` (columns and `exact`; not phase or path,
  /// which are not against t: UsageError). `run` names the run's curves in
  /// the legend when pages compare runs.
  /// `run_color`, when given, colours every curve of the run (comparisons
  /// tell runs apart by colour); otherwise each panel has its own.
  PagePlotCollector(const TrajectoryInfo&, const std::vector<std::string>& panels, const std::string& run,
                    std::optional<render::Color> run_color = std::nullopt);

  /// One solver row of `run`: t first, then the model's columns. A page's
  /// series lie on the mesh t_n = n dt; an adaptive run's rows fall between
  /// its points, so it gives the page its rows on the mesh from its dense
  /// output instead (Trajectory::row_at inside the step just taken).
  void observe(const Trajectory& run, std::span<const double> row);

  /// The panels collected; the collector is spent.
  std::vector<render::PagePanel> take_panels();

 private:
  struct Feed {
    size_t panel, series;
    std::function<double(std::span<const double>)> value;
  };
  void add(std::span<const double> row);

  std::vector<render::PagePanel> panels_;
  std::vector<Feed> feeds_;
  double grid_ = 0;         ///< the mesh's dt for an adaptive run, 0 when its rows are on the mesh
  long long next_ = 0;      ///< the next mesh point an adaptive run owes the page
  std::vector<double> on_grid_;
};

/// Adds one run's panels to a page's: each curve joins the panel of the same
/// label (new panels go last). Comparisons call it once per run.
void merge_page_panels(std::vector<render::PagePanel>& page, std::vector<render::PagePanel> run);

}  // namespace vibra::scenes
