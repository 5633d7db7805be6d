// The plot job: a model's run (or one run per compared value) drawn as a static figure or a page of zoomable plots.
#include "jobs/plot_job.hpp"

#include <algorithm>
#include <filesystem>
#include <memory>

#include "core/comparison.hpp"
#include "core/error.hpp"
#include "core/error_column.hpp"
#include "core/models/model.hpp"
#include "jobs/list_option.hpp"
#include "render/encode/output_kind.hpp"
#include "render/output/output_path.hpp"
#include "render/output/stop_signal.hpp"
#include "render/page/html_page.hpp"
#include "render/plot/figure.hpp"
#include "scenes/config/scene_config.hpp"
#include "scenes/diagrams/comparison_labels.hpp"
#include "scenes/figures/comparison_figure.hpp"
#include "scenes/figures/trajectory_figure.hpp"
#include "scenes/overlays/annotations.hpp"
#include "scenes/overlays/run_caption.hpp"
#include "scenes/panels/page_plot_collector.hpp"

namespace vibra::app {

namespace {
int figure_height(size_t panels) { return panels > 2 ? 960 : 720; }

/// The picture's size: --size, or 1280 wide and tall enough for its panels.
void figure_size(const PlotRequest& r, size_t panels, int& width, int& height) {
  width = 1280, height = figure_height(panels);
  if (!r.size.empty()) scenes::parse_size(r.size, width, height);
}

render::Figure comparison_plot(const PlotRequest& r, const Parameters& parameters) {
  if (r.compare.size() > 1) throw UsageError("--compare is given " + std::to_string(r.compare.size()) +
                                             " times: compare one key at a time, e.g. --compare dt=0.1,0.05");
  Comparison comparison(find_model(r.model), parameters, parse_comparison(r.compare[0]));
  const TrajectoryInfo& info = comparison.trajectory(0).info();
  const std::vector<std::string> panels =
      r.panels.empty() ? scenes::default_comparison_panels(info) : word_list("--panels", r.panels);
  int width, height;
  figure_size(r, panels.size(), width, height);
  return scenes::comparison_figure(comparison, panels, width, height, scenes::comparison_caption(r.model, comparison));
}

/// `--panels error` plots a column the model does not have: u - u_exact.
bool wants_error(const std::vector<std::string>& panels) {
  return std::find(panels.begin(), panels.end(), "error") != panels.end();
}

/// `--annotate LIST`: whether to mark the mesh (the one annotation plot draws).
bool marks_mesh(const PlotRequest& r) {
  if (r.annotate.empty()) return false;
  for (const auto& name : word_list("--annotate", r.annotate)) scenes::check_annotation_name(name, "plot");
  if (!r.compare.empty()) throw UsageError("--annotate mesh marks one run's steps: drop --compare, or --annotate");
  return true;
}

render::Figure trajectory_plot(const PlotRequest& r, const Parameters& parameters, bool mark_mesh) {
  std::unique_ptr<Trajectory> trajectory = find_model(r.model).build(parameters);
  const std::vector<std::string> panels =
      r.panels.empty() ? scenes::default_plot_panels(trajectory->info()) : word_list("--panels", r.panels);
  if (wants_error(panels)) trajectory = with_error_column(std::move(trajectory));
  int width, height;
  figure_size(r, panels.size(), width, height);
  const std::string title = scenes::run_caption(r.model, parameters, trajectory->info().mesh);
  return scenes::trajectory_figure(*trajectory, panels, width, height, title, mark_mesh);
}

/// FIGURE.html: the run's time series as a page of linked, zoomable plots.
void write_figure_page(const PlotRequest& r, const std::filesystem::path& file) {
  if (!r.size.empty())
    throw UsageError("--size sets a picture's size, and a page's plots fit the browser window: drop --size");
  const Parameters parameters = model_settings(r.model, r.settings);
  std::unique_ptr<Trajectory> trajectory = find_model(r.model).build(parameters);
  const std::vector<std::string> panels =
      r.panels.empty() ? scenes::page_panel_names(trajectory->info()) : word_list("--panels", r.panels);
  if (wants_error(panels)) trajectory = with_error_column(std::move(trajectory));
  const TrajectoryInfo& info = trajectory->info();
  scenes::PagePlotCollector collector(info, panels, r.model);
  std::vector<double> row(trajectory->width());
  do {
    trajectory->row(row);
    collector.observe(*trajectory, row);
    poll_stop(trajectory->index());
  } while (trajectory->advance());
  render::LecturePage page;
  page.title = "vibra: " + r.model;
  page.panels = collector.take_panels();
  page.facts = scenes::run_facts(r.model, parameters, info.mesh);
  page.command_line = r.command_line;
  render::write_text_file(file, render::lecture_page_html(page));
}
}  // namespace

std::string run_plot(const PlotRequest& r) {
  if (r.model.empty()) throw UsageError("vibra plot needs a MODEL, e.g. vibra plot pendulum -o pendulum.png");
  if (r.output.empty())
    throw UsageError("vibra plot needs an output file: add -o FILE.png, FILE.svg, FILE.pdf or FILE.html");
  const bool page = render::classify_output(r.output) == render::OutputKind::page;
  if (page && !r.annotate.empty())
    throw UsageError("--annotate marks a picture; a page's plots are zoomable: give -o FILE.png, .svg or .pdf");
  if (page && r.transparent)
    throw UsageError("--transparent is for pictures; a page has no background to drop: give -o FILE.png, .svg or .pdf");
  if (!page) render::require_picture_extension(r.output);
  const render::OutputTarget target = render::resolve_output(r.output);
  if (page) {
    write_figure_page(r, target.file);
  } else {
    const Parameters parameters = model_settings(r.model, r.settings);
    const bool mark_mesh = marks_mesh(r);
    render::Figure figure = r.compare.empty() ? trajectory_plot(r, parameters, mark_mesh) : comparison_plot(r, parameters);
    figure.set_transparent(r.transparent);
    figure.write(target.file);
  }
  return target.shown();
}

}  // namespace vibra::app
