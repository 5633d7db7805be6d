#include "scenes/trajectory_figure.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "core/parameters.hpp"
#include "render/stop_signal.hpp"

namespace vibra::scenes {

namespace {
using render::palette::blue;

int column_index(const TrajectoryInfo& info, const std::string& name) {
  const auto& c = info.columns;
  const auto it = std::find(c.begin(), c.end(), name);
  return it == c.end() ? -1 : static_cast<int>(it - c.begin());
}

bool has_path(const TrajectoryInfo& info) { return column_index(info, "x") > 0 && column_index(info, "y") > 0; }

/// The main quantity's velocity: the column v<name> where the model has one
/// (vx for x), else the column after the main quantity (v for u, omega for theta).
int velocity_column(const TrajectoryInfo& info) {
  const int named = column_index(info, "v" + info.columns[1]);
  return named > 0 ? named : 2;
}

/// A column's name as the reader knows it: Greek letters, italics, subscripts.
std::string quantity_markup(const std::string& column) {
  if (column == "theta") return "<i>θ</i> (rad)";
  if (column == "omega") return "<i>ω</i> (rad per time unit)";
  if (column == "S") return "<i>S</i> / <i>mg</i>, wire force";
  if (column == "D") return "<i>D</i> / <i>mg</i>, air drag";
  if (column.size() == 2 && column[0] == 'v') return "<i>v<sub>" + column.substr(1) + "</sub></i>";
  if (column.size() == 1) return "<i>" + column + "</i>";
  return column;
}

/// A series fed from two columns of every row (column 0 is t).
struct Feed {
  render::Series* series;
  int x_column, y_column;
};
}  // namespace

std::vector<std::string> plot_panel_names(const TrajectoryInfo& info) {
  std::vector<std::string> names(info.columns.begin() + 1, info.columns.end());
  names.push_back("exact");
  names.push_back("phase");
  if (has_path(info)) names.push_back("path");
  return names;
}

std::vector<std::string> default_plot_panels(const TrajectoryInfo& info) {
  if (has_path(info)) return {"path"};
  if (column_index(info, "S") > 0 && column_index(info, "D") > 0) return {info.columns[1], "S", "D"};
  return {info.columns[1]};
}

render::Color time_panel_color(int k) {
  using namespace render::palette;
  const render::Color colors[] = {blue, green, purple, orange, sky};
  return colors[k % 5];
}

std::vector<std::string> ordered_plot_panels(const TrajectoryInfo& info, const std::vector<std::string>& panels) {
  const std::vector<std::string> valid = plot_panel_names(info);
  for (const auto& name : panels) {
    if (std::find(valid.begin(), valid.end(), name) != valid.end()) continue;
    std::string list;
    for (const auto& v : valid) list += (list.empty() ? "" : ", ") + v;
    const std::string near = closest_match(name, valid);
    throw UsageError("unknown panel '" + name + "'" + (near.empty() ? "" : " (did you mean '" + near + "'?)") +
                     ": choose from " + list);
  }
  if (panels.empty()) throw UsageError("--panels is empty: name at least one panel, e.g. --panels " + valid[0]);
  const bool with_exact = std::find(panels.begin(), panels.end(), "exact") != panels.end();
  if (with_exact && !info.exact)
    throw UsageError("this run has no exact solution to overlay: drop 'exact' from --panels (undamped always has one, "
                     "pendulum with alpha=0 its small-angle solution, two-body a circular orbit)");
  if (!std::isfinite(info.mesh.T)) throw UsageError("a plot needs a finite end time: give T or periods");

  // `exact` joins the main quantity's panel, or stands in for it when it is not listed.
  const std::string& main = info.columns[1];
  std::vector<std::string> order;
  for (const auto& name : panels) {
    const std::string panel = name == "exact" ? main : name;
    if (panel != main || std::find(order.begin(), order.end(), main) == order.end()) order.push_back(panel);
  }
  return order;
}

render::Figure trajectory_figure(Trajectory& trajectory, const std::vector<std::string>& panels, int width, int height,
                                 const std::string& title) {
  const TrajectoryInfo& info = trajectory.info();
  const std::vector<std::string> order = ordered_plot_panels(info, panels);
  const bool with_exact = std::find(panels.begin(), panels.end(), "exact") != panels.end();
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
    feeds.push_back({&figure.add_curve(p, overlay ? "numerical" : "", {time_panel_color(time_panels++), 2.2}, 0, T), 0, column});
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
