// Collects a run's samples into the lecture page's plots, with the panels a page shows by default.
#include "scenes/panels/page_plot_collector.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "render/draw/text.hpp"
#include "scenes/panels/plot_panels.hpp"

namespace vibra::scenes {


std::vector<std::string> page_panel_names(const TrajectoryInfo& info) {
  if (column_index(info, "S") > 0 && column_index(info, "D") > 0) return {info.columns[1], "S", "D"};
  std::vector<std::string> names(info.columns.begin() + 1, info.columns.end());
  if (info.exact) names.push_back("exact");
  return names;
}

PagePlotCollector::PagePlotCollector(const TrajectoryInfo& info, const std::vector<std::string>& panels,
                                     const std::string& run, std::optional<render::Color> run_color) {
  const std::vector<std::string> order = ordered_plot_panels(info, panels);
  const bool with_exact = std::find(panels.begin(), panels.end(), "exact") != panels.end();
  const TimeMesh& mesh = info.mesh;
  if (mesh.adaptive()) grid_ = mesh.dt;
  auto data = [&] { return render::PageSeriesData(0, mesh.T, mesh.dt, mesh.steps + 1); };
  for (const auto& name : order) {
    if (name == "phase" || name == "path" || name == "friction")
      throw UsageError("panel '" + name + "' is not against t, and a page plots against t: drop it, or draw it in "
                       "-o FILE.png, FILE.svg or FILE.pdf");
    const int column = column_index(info, name);
    const double factor = display_factor(name);
    // The same words as the video's panel title, without markup (uPlot draws none).
    render::PagePanel panel{render::markup_plain_text(quantity_markup(name)), {}};
    feeds_.push_back({panels_.size(), 0, [column, factor](std::span<const double> row) { return factor * row[column]; }});
    panel.series.push_back(
        {name, run, run_color.value_or(time_panel_color(static_cast<int>(panels_.size()))), false, data()});
    if (with_exact && name == info.columns[1]) {
      feeds_.push_back({panels_.size(), 1, [exact = info.exact, factor](std::span<const double> row) {
                          return factor * exact(row[0]);
                        }});
      panel.series.push_back({name + " " + info.exact_label, info.exact_label, render::palette::vermillion, true, data()});
    }
    panels_.push_back(std::move(panel));
  }
}

void PagePlotCollector::observe(const Trajectory& run, std::span<const double> row) {
  if (grid_ <= 0) return add(row);
  on_grid_.resize(row.size());
  for (double t; next_ <= run.info().mesh.steps && (t = next_ * grid_) <= row[0]; ++next_) {
    run.row_at(t, on_grid_);
    add(on_grid_);
  }
}

void PagePlotCollector::add(std::span<const double> row) {
  for (const Feed& f : feeds_) panels_[f.panel].series[f.series].data.add(f.value(row));
}

std::vector<render::PagePanel> PagePlotCollector::take_panels() { return std::move(panels_); }

void merge_page_panels(std::vector<render::PagePanel>& page, std::vector<render::PagePanel> run) {
  for (auto& panel : run) {
    const auto same = std::find_if(page.begin(), page.end(), [&](const auto& p) { return p.label == panel.label; });
    if (same == page.end()) {
      page.push_back(std::move(panel));
      continue;
    }
    for (auto& series : panel.series) same->series.push_back(std::move(series));
  }
}

}  // namespace vibra::scenes
