// The figure of vibra plot: a trajectory streamed once into the named panels, stacked.
#include "scenes/figures/trajectory_figure.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "render/output/stop_signal.hpp"
#include "scenes/figures/friction_panel.hpp"
#include "scenes/figures/mesh_marks.hpp"
#include "scenes/panels/rows_inside_step.hpp"

namespace vibra::scenes {

namespace {
using render::palette::blue;

/// A series fed from two columns of every row (column 0 is t).
struct Feed {
  render::Series* series;
  int x_column, y_column;
  double x_factor = 1, y_factor = 1;  ///< display_factor of each column
};

/// The figure being built and what its panels are fed from.
struct TrajectoryPlot {
  render::Figure& figure;
  const TrajectoryInfo& info;
  int width;
  bool with_exact;
  std::vector<Feed> feeds;
  std::vector<Feed> starts;  ///< markers at the start of paths, fed the first row only
  int time_panels = 0;
  std::optional<FrictionPanel> friction;
  std::optional<MeshMarks> mesh;
};

/// The path (y against x) or the phase plane, with a marker at the start.
void add_plane_panel(TrajectoryPlot& plot, const std::string& name) {
  const TrajectoryInfo& info = plot.info;
  const PhaseVelocityAxis phase = phase_velocity_axis(info);
  const int x = name == "path" ? column_index(info, "x") : 1;
  const int y = name == "path" ? column_index(info, "y") : phase.column;
  const int p = plot.figure.add_panel({name == "path" ? quantity_markup(info.columns[y]) : phase.label,
                                       quantity_markup(info.columns[x]), render::AxisScale::linear,
                                       render::AxisScale::linear, name == "path" || phase.equal_scales});
  const double fx = display_factor(info.columns[x]), fy = name == "path" ? display_factor(info.columns[y]) : phase.factor;
  plot.feeds.push_back({&plot.figure.add_path(p, "", {blue, 2}), x, y, fx, fy});
  plot.starts.push_back({&plot.figure.add_points(p, "start", {render::palette::vermillion, 0, false, true}), x, y, fx, fy});
}

/// A column against t, with the exact solution over the main quantity when asked.
void add_time_panel(TrajectoryPlot& plot, const std::string& name) {
  const TrajectoryInfo& info = plot.info;
  const double T = info.mesh.T;
  const int column = column_index(info, name);
  const int p = plot.figure.add_panel({quantity_markup(name), "<i>t</i>", render::AxisScale::linear,
                                       render::AxisScale::linear, false, std::make_pair(0.0, T),
                                       plot.mesh ? plot.mesh->ticks() : std::vector<double>{}});
  const bool overlay = plot.with_exact && name == info.columns[1];
  const double f = display_factor(name);
  const render::Color color = time_panel_color(plot.time_panels++);
  plot.feeds.push_back({&plot.figure.add_curve(p, overlay ? "numerical" : "", {color, 2.2}, 0, T), 0, column, 1, f});
  if (plot.mesh) plot.mesh->mark_panel(plot.figure, p, column, f, color);
  if (!overlay) return;
  // The exact solution is a function: sample it at least as finely as the
  // mesh (so its envelope holds every peak) and at least 4 times per pixel column.
  render::Series& exact = plot.figure.add_curve(p, info.exact_label, {render::palette::vermillion, 2, true}, 0, T);
  const long long samples = std::max(4LL * plot.width, info.mesh.steps);
  for (long long i = 0; i <= samples; ++i) exact.add(T * i / samples, f * info.exact(T * i / samples));
}

/// Every step, and rows inside the steps, into the panels' series.
void feed_trajectory(TrajectoryPlot& plot, Trajectory& trajectory) {
  std::vector<double> row(trajectory.width());
  trajectory.row(row);
  for (const Feed& f : plot.starts) f.series->add(f.x_factor * row[f.x_column], f.y_factor * row[f.y_column]);
  auto feed = [&](std::span<const double> r) {
    for (const Feed& f : plot.feeds) f.series->add(f.x_factor * r[f.x_column], f.y_factor * r[f.y_column]);
    if (plot.friction) plot.friction->observe(0, r);
  };
  const double spacing = inside_step_spacing(plot.info.mesh, plot.width);
  double previous = trajectory.t();
  do {
    rows_inside_step(trajectory, previous, spacing, row, feed);
    trajectory.row(row);
    feed(row);
    if (plot.mesh) plot.mesh->observe_step(row);
    previous = trajectory.t();
    poll_stop(trajectory.index());
  } while (trajectory.advance());
}
}  // namespace

render::Figure trajectory_figure(Trajectory& trajectory, const std::vector<std::string>& panels, int width, int height,
                                 const std::string& title, bool mark_mesh) {
  const TrajectoryInfo& info = trajectory.info();
  render::Figure figure(width, height, title);
  TrajectoryPlot plot{figure, info, width, std::find(panels.begin(), panels.end(), "exact") != panels.end()};
  if (mark_mesh) plot.mesh.emplace(info, width);
  for (const auto& name : ordered_plot_panels(info, panels)) {
    if (name == "friction") plot.friction.emplace(figure, std::vector<FrictionPanel::Member>{{&info, blue, ""}});
    else if (name == "path" || name == "phase") add_plane_panel(plot, name);
    else add_time_panel(plot, name);
  }
  feed_trajectory(plot, trajectory);
  if (plot.friction) plot.friction->finish();
  return figure;
}

}  // namespace vibra::scenes
