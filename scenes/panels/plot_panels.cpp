// What `vibra plot` can draw for a model, shared by the figure of one run and that of a comparison.
#include "scenes/panels/plot_panels.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "core/input/parameters.hpp"

namespace vibra::scenes {

namespace {
bool has_path(const TrajectoryInfo& info) { return column_index(info, "x") > 0 && column_index(info, "y") > 0; }
}  // namespace

int column_index(const TrajectoryInfo& info, const std::string& name) {
  const auto& c = info.columns;
  const auto it = std::find(c.begin(), c.end(), name);
  return it == c.end() ? -1 : static_cast<int>(it - c.begin());
}

double display_factor(const std::string& column) { return column == "theta" ? 180 / M_PI : 1; }

std::string quantity_markup(const std::string& column) {
  if (column == "theta") return "<i>θ</i> (°)";
  if (column == "omega") return "<i>ω</i> (rad per time unit)";
  if (column == "S") return "<i>S</i> / <i>mg</i>, wire force";
  if (column == "D") return "<i>D</i> / <i>mg</i>, air drag";
  if (column == "v") return "<i>v</i>  velocity";
  if (column.size() == 2 && column[0] == 'v') return "<i>v<sub>" + column.substr(1) + "</sub></i>";
  if (column.size() == 1) return "<i>" + column + "</i>";
  return column;
}

std::string quantity_symbol(const std::string& column) {
  return column == "theta" ? "<i>θ</i>" : "<i>" + column + "</i>";
}

PhaseVelocityAxis phase_velocity_axis(const TrajectoryInfo& info) {
  const int v = velocity_column(info);
  const std::string& main = info.columns[1], &velocity = info.columns[v];
  if (!(info.mesh.period > 0)) return {v, display_factor(velocity), quantity_markup(velocity), false};
  const double w = 2 * M_PI / info.mesh.period;
  if (main == "theta") return {v, display_factor(main) / w, "<i>θ</i>′ / <i>ω</i><sub>0</sub> (°)", true};
  const std::string symbol = velocity == "v" ? "<i>v</i>" : quantity_markup(velocity);
  return {v, display_factor(main) / w, symbol + " / <i>ω</i>", true};
}

std::vector<std::string> plot_panel_names(const TrajectoryInfo& info) {
  std::vector<std::string> names(info.columns.begin() + 1, info.columns.end());
  names.push_back("exact");
  names.push_back("phase");
  if (has_path(info)) names.push_back("path");
  if (info.spring_and_friction) names.push_back("friction");
  return names;
}

std::vector<std::string> default_plot_panels(const TrajectoryInfo& info) {
  if (has_path(info)) return {"path"};
  if (column_index(info, "S") > 0 && column_index(info, "D") > 0) return {info.columns[1], "S", "D"};
  return {info.columns[1]};
}

std::vector<std::string> panel_order(const TrajectoryInfo& info, const std::vector<std::string>& panels) {
  const std::vector<std::string> valid = plot_panel_names(info);
  for (const auto& name : panels)
    if (std::find(valid.begin(), valid.end(), name) == valid.end()) reject_unknown_panel(name, valid);
  if (panels.empty()) throw UsageError("--panels is empty: name at least one panel, e.g. --panels " + valid[0]);
  const std::string& main = info.columns[1];
  std::vector<std::string> order;
  for (const auto& name : panels) {
    const std::string panel = name == "exact" ? main : name;
    if (panel != main || std::find(order.begin(), order.end(), main) == order.end()) order.push_back(panel);
  }
  return order;
}

void reject_unknown_panel(const std::string& name, const std::vector<std::string>& valid) {
  std::string list;
  for (const auto& v : valid) list += (list.empty() ? "" : ", ") + v;
  const std::string near = closest_match(name, valid);
  throw UsageError("unknown panel '" + name + "'" + (near.empty() ? "" : " (did you mean '" + near + "'?)") +
                   ": choose from " + list);
}

const char* const kRunsWithExactSolution =
    "undamped always has one, pendulum with alpha=0 its small-angle solution, two-body a circular orbit";

std::vector<std::string> ordered_plot_panels(const TrajectoryInfo& info, const std::vector<std::string>& panels) {
  std::vector<std::string> order = panel_order(info, panels);
  if (std::find(panels.begin(), panels.end(), "exact") != panels.end() && !info.exact)
    throw UsageError(std::string("this run has no exact solution to overlay: drop 'exact' from --panels (") +
                     kRunsWithExactSolution + ")");
  if (!std::isfinite(info.mesh.T)) throw UsageError("a plot needs a finite end time: give T or periods");
  return order;
}

render::Color time_panel_color(int k) {
  using namespace render::palette;
  const render::Color colors[] = {blue, green, purple, orange, sky};
  return colors[k % 5];
}

}  // namespace vibra::scenes
