#include "scenes/trajectory_figure.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "render/stop_signal.hpp"

namespace vibra::scenes {

namespace {
using render::palette::blue;

/// Colours for the time panels in turn; vermillion is kept for the exact solution.
render::Color panel_color(int k) {
  using namespace render::palette;
  const render::Color colors[] = {blue, green, purple, orange, sky};
  return colors[k % 5];
}

/// A series fed from two columns of every row (column 0 is t).
struct Feed {
  render::Series* series;
  int x_column, y_column;
};
}  // namespace

render::Figure trajectory_figure(Trajectory& trajectory, const std::vector<std::string>& panels, int width, int height,
                                 const std::string& title) {
  const TrajectoryInfo& info = trajectory.info();
  const std::vector<std::string> order = panel_order(info, panels);
  const bool with_exact = std::find(panels.begin(), panels.end(), "exact") != panels.end();
  if (with_exact && !info.exact)
    throw UsageError("this run has no exact solution to overlay: drop 'exact' from --panels (undamped always has one, "
                     "pendulum with alpha=0 its small-angle solution, two-body a circular orbit)");
  if (!std::isfinite(info.mesh.T)) throw UsageError("a plot needs a finite end time: give T or periods");
  const std::string& main = info.columns[1];

  render::Figure figure(width, height, title);
  const double T = info.mesh.T;
  std::vector<Feed> feeds;
  std::vector<Feed> starts;  // markers at the start of paths, fed the first row only
  int time_panels = 0;
  for (const auto& name : order) {
    if (name == "path" || name == "phase") {
      const int x = name == "path" ? column_index(info, "x") : 1;
      const int y = name == "path" ? column_index(info, "y") : velocity_column(info);
      const int p = figure.add_panel({quantity_markup(info.columns[y]), quantity_markup(info.columns[x]),
                                      render::AxisScale::linear, render::AxisScale::linear, name == "path"});
      feeds.push_back({&figure.add_path(p, "", {blue, 2}), x, y});
      starts.push_back({&figure.add_points(p, "start", {render::palette::vermillion, 0, false, true}), x, y});
      continue;
    }
    const int column = column_index(info, name);
    const int p = figure.add_panel({quantity_markup(name), "<i>t</i>", render::AxisScale::linear,
                                    render::AxisScale::linear, false, std::make_pair(0.0, T)});
    const bool overlay = with_exact && name == main;
    feeds.push_back({&figure.add_curve(p, overlay ? "numerical" : "", {panel_color(time_panels++), 2.2}, 0, T), 0, column});
    if (overlay) {
      // The exact solution is a function: sample it at least as finely as the
      // mesh (so its envelope holds every peak) and at least 4 times per pixel column.
      render::Series& exact = figure.add_curve(p, info.exact_label, {render::palette::vermillion, 2, true}, 0, T);
      const long long samples = std::max(4LL * width, info.mesh.steps);
      for (long long i = 0; i <= samples; ++i) exact.add(T * i / samples, info.exact(T * i / samples));
    }
  }

  std::vector<double> row(trajectory.width());
  trajectory.row(row);
  for (const Feed& f : starts) f.series->add(row[f.x_column], row[f.y_column]);
  do {
    trajectory.row(row);
    for (const Feed& f : feeds) f.series->add(row[f.x_column], row[f.y_column]);
    if ((trajectory.index() & 0xffff) == 0) render::throw_if_stop_requested();
  } while (trajectory.advance());
  return figure;
}

}  // namespace vibra::scenes
