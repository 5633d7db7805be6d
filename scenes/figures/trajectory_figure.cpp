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
}  // namespace

render::Figure trajectory_figure(Trajectory& trajectory, const std::vector<std::string>& panels, int width, int height,
                                 const std::string& title, bool mark_mesh) {
  const TrajectoryInfo& info = trajectory.info();
  const std::vector<std::string> order = ordered_plot_panels(info, panels);
  const bool with_exact = std::find(panels.begin(), panels.end(), "exact") != panels.end();
  const std::string& main = info.columns[1];

  render::Figure figure(width, height, title);
  const double T = info.mesh.T;
  std::vector<Feed> feeds;
  std::vector<Feed> starts;  // markers at the start of paths, fed the first row only
  int time_panels = 0;
  std::optional<FrictionPanel> friction;
  std::optional<MeshMarks> mesh;
  if (mark_mesh) mesh.emplace(info, width);
  for (const auto& name : order) {
    if (name == "friction") {
      friction.emplace(figure, std::vector<FrictionPanel::Member>{{&info, blue, ""}});
      continue;
    }
    if (name == "path" || name == "phase") {
      const PhaseVelocityAxis phase = phase_velocity_axis(info);
      const int x = name == "path" ? column_index(info, "x") : 1;
      const int y = name == "path" ? column_index(info, "y") : phase.column;
      const int p = figure.add_panel({name == "path" ? quantity_markup(info.columns[y]) : phase.label,
                                      quantity_markup(info.columns[x]), render::AxisScale::linear,
                                      render::AxisScale::linear, name == "path" || phase.equal_scales});
      const double fx = display_factor(info.columns[x]), fy = name == "path" ? display_factor(info.columns[y]) : phase.factor;
      feeds.push_back({&figure.add_path(p, "", {blue, 2}), x, y, fx, fy});
      starts.push_back({&figure.add_points(p, "start", {render::palette::vermillion, 0, false, true}), x, y, fx, fy});
      continue;
    }
    const int column = column_index(info, name);
    const int p = figure.add_panel({quantity_markup(name), "<i>t</i>", render::AxisScale::linear,
                                    render::AxisScale::linear, false, std::make_pair(0.0, T),
                                    mesh ? mesh->ticks() : std::vector<double>{}});
    const bool overlay = with_exact && name == main;
    const double f = display_factor(name);
    const render::Color color = time_panel_color(time_panels++);
    feeds.push_back({&figure.add_curve(p, overlay ? "numerical" : "", {color, 2.2}, 0, T), 0, column, 1, f});
    if (mesh) mesh->mark_panel(figure, p, column, f, color);
    if (overlay) {
      // The exact solution is a function: sample it at least as finely as the
      // mesh (so its envelope holds every peak) and at least 4 times per pixel column.
      render::Series& exact = figure.add_curve(p, info.exact_label, {render::palette::vermillion, 2, true}, 0, T);
      const long long samples = std::max(4LL * width, info.mesh.steps);
      for (long long i = 0; i <= samples; ++i) exact.add(T * i / samples, f * info.exact(T * i / samples));
    }
  }

  std::vector<double> row(trajectory.width());
  trajectory.row(row);
  for (const Feed& f : starts) f.series->add(f.x_factor * row[f.x_column], f.y_factor * row[f.y_column]);
  auto feed = [&](std::span<const double> r) {
    for (const Feed& f : feeds) f.series->add(f.x_factor * r[f.x_column], f.y_factor * r[f.y_column]);
    if (friction) friction->observe(0, r);
  };
  const double spacing = inside_step_spacing(info.mesh, width);
  double previous = trajectory.t();
  do {
    rows_inside_step(trajectory, previous, spacing, row, feed);
    trajectory.row(row);
    feed(row);
    if (mesh) mesh->observe_step(row);
    previous = trajectory.t();
    if ((trajectory.index() & 0xffff) == 0) render::throw_if_stop_requested();
  } while (trajectory.advance());
  if (friction) friction->finish();
  return figure;
}

}  // namespace vibra::scenes
