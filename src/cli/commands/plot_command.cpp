// Registers vibra plot: a static figure of a run's panels.
#include <algorithm>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "jobs/list_option.hpp"
#include "cli/command_line.hpp"
#include "cli/commands.hpp"
#include "cli/manuals/model_help.hpp"
#include "cli/wrote_message.hpp"
#include "core/error.hpp"
#include "core/error_column.hpp"
#include "render/encode/output_kind.hpp"
#include "render/output/output_path.hpp"
#include "render/output/stop_signal.hpp"
#include "render/page/html_page.hpp"
#include "render/plot/figure.hpp"
#include "scenes/diagrams/comparison_labels.hpp"
#include "scenes/overlays/annotations.hpp"
#include "scenes/figures/comparison_figure.hpp"
#include "scenes/figures/trajectory_figure.hpp"
#include "scenes/panels/page_plot_collector.hpp"
#include "scenes/overlays/run_caption.hpp"
#include "scenes/config/scene_config.hpp"

namespace vibra::cli {

namespace {
struct PlotOptions {
  std::string model;
  std::vector<std::string> settings;
  std::string output;
  std::string panels;
  std::string size;
  std::vector<std::string> compare;
  std::string annotate;
  bool help = false;
  bool quiet = false;
  bool transparent = false;
};

constexpr const char* kUsage =
    "Usage: vibra plot MODEL [--set KEY=VALUE]... [--compare KEY=V1,V2,...] -o FILE.png|svg|pdf|html [--panels LIST] "
    "[--annotate mesh] [--size WxH]\n";
constexpr const char* kExamples =
    "\nPanels: any column of the model but t (against t; neighbours share the t axis), exact (the exact\n"
    "solution over the main quantity, dashed), error (main quantity - exact solution, where one is known),\n"
    "phase (main quantity against its velocity), path (y against x,\n"
    "equal aspect; elastic-pendulum and two-body), friction (sliding-box: the spring force s(u) against u,\n"
    "the friction band +-mu where the box can rest, and the run's turning points).\n"
    "Defaults: theta,S,D for the pendulums, path for elastic-pendulum and two-body, the main quantity otherwise.\n"
    "\n--compare KEY=V1,V2,... runs the model once per value (up to 8) of one key: scheme, dt,\n"
    "steps_per_period or a model key. Every panel draws one curve per run, the exact solution dashed where\n"
    "known; a run that grows without bound is marked 'left the view at t = ...', one that overflows 'blew up at t = ...'. Default panels: the main quantity and\n"
    "phase (path for elastic-pendulum and two-body).\n"
    "\nExamples:\n"
    "  vibra plot pendulum -o pendulum.png                       # theta, S and D against t\n"
    "  vibra plot undamped --panels u,exact --set periods=4 -o u.svg\n"
    "  vibra plot elastic-pendulum --set Theta=40 --set eps=0.1 -o path.pdf\n"
    "  vibra plot undamped --compare scheme=forward-euler,backward-euler,crank-nicolson,rk4 --set steps_per_period=40 \\\n"
    "      --set periods=4 -o schemes.png\n"
    "  vibra plot sliding-box --compare alpha=0,1,2,4 --panels friction,u -o springs.png   # Exercise 1.23\n"
    "  vibra plot undamped --set scheme=staggered --set steps_per_period=8 --set periods=2 --panels u,v \\\n"
    "      --annotate mesh -o mesh.png                           # Fig 1.12\n"
    "  vibra plot pendulum --set periods=200 -o pendulum.html   # interactive, zoomable (time panels only)\n";

int figure_height(size_t panels) { return panels > 2 ? 960 : 720; }

render::Figure comparison_plot(const PlotOptions& o, const Parameters& parameters) {
  if (o.compare.size() > 1) throw UsageError("--compare is given " + std::to_string(o.compare.size()) +
                                             " times: compare one key at a time, e.g. --compare dt=0.1,0.05");
  Comparison comparison(find_model(o.model), parameters, parse_comparison(o.compare[0]));
  const TrajectoryInfo& info = comparison.trajectory(0).info();
  const std::vector<std::string> panels =
      o.panels.empty() ? scenes::default_comparison_panels(info) : app::word_list("--panels", o.panels);
  int width = 1280, height = figure_height(panels.size());
  if (!o.size.empty()) scenes::parse_size(o.size, width, height);
  return scenes::comparison_figure(comparison, panels, width, height, scenes::comparison_caption(o.model, comparison));
}

/// `--panels error` plots a column the model does not have: u - u_exact.
bool wants_error(const std::vector<std::string>& panels) {
  return std::find(panels.begin(), panels.end(), "error") != panels.end();
}

/// `--annotate LIST`: whether to mark the mesh (the one annotation plot draws).
bool marks_mesh(const PlotOptions& o) {
  if (o.annotate.empty()) return false;
  for (const auto& name : app::word_list("--annotate", o.annotate)) scenes::check_annotation_name(name, "plot");
  if (!o.compare.empty()) throw UsageError("--annotate mesh marks one run's steps: drop --compare, or --annotate");
  return true;
}

render::Figure trajectory_plot(const PlotOptions& o, const Parameters& parameters, bool mark_mesh) {
  std::unique_ptr<Trajectory> trajectory = find_model(o.model).build(parameters);
  const std::vector<std::string> panels =
      o.panels.empty() ? scenes::default_plot_panels(trajectory->info()) : app::word_list("--panels", o.panels);
  if (wants_error(panels)) trajectory = with_error_column(std::move(trajectory));
  int width = 1280, height = figure_height(panels.size());
  if (!o.size.empty()) scenes::parse_size(o.size, width, height);
  const std::string title = scenes::run_caption(o.model, parameters, trajectory->info().mesh);
  return scenes::trajectory_figure(*trajectory, panels, width, height, title, mark_mesh);
}

/// FIGURE.html: the run's time series as a page of linked, zoomable plots.
void write_figure_page(const PlotOptions& o, const std::filesystem::path& file) {
  if (!o.size.empty())
    throw UsageError("--size sets a picture's size, and a page's plots fit the browser window: drop --size");
  const Parameters parameters = model_settings(o.model, o.settings);
  std::unique_ptr<Trajectory> trajectory = find_model(o.model).build(parameters);
  const std::vector<std::string> panels =
      o.panels.empty() ? scenes::page_panel_names(trajectory->info()) : app::word_list("--panels", o.panels);
  if (wants_error(panels)) trajectory = with_error_column(std::move(trajectory));
  const TrajectoryInfo& info = trajectory->info();
  scenes::PagePlotCollector collector(info, panels, o.model);
  std::vector<double> row(trajectory->width());
  do {
    trajectory->row(row);
    collector.observe(*trajectory, row);
    if ((trajectory->index() & 0xffff) == 0) render::throw_if_stop_requested();
  } while (trajectory->advance());
  render::LecturePage page;
  page.title = "vibra: " + o.model;
  page.panels = collector.take_panels();
  page.facts = scenes::run_facts(o.model, parameters, info.mesh);
  page.command_line = command_line();
  render::write_text_file(file, render::lecture_page_html(page));
}

void run_plot(const PlotOptions& o) {
  if (o.help || o.model.empty()) {
    print_model_help(std::string(kUsage) + kExamples + "\n", o.model);
    if (!o.help) throw UsageError("vibra plot needs a MODEL, e.g. vibra plot pendulum -o pendulum.png");
    return;
  }
  if (o.output.empty())
    throw UsageError("vibra plot needs an output file: add -o FILE.png, FILE.svg, FILE.pdf or FILE.html");
  const bool page = render::classify_output(o.output) == render::OutputKind::page;
  if (page && !o.annotate.empty())
    throw UsageError("--annotate marks a picture; a page's plots are zoomable: give -o FILE.png, .svg or .pdf");
  if (page && o.transparent)
    throw UsageError("--transparent is for pictures; a page has no background to drop: give -o FILE.png, .svg or .pdf");
  if (!page) render::require_picture_extension(o.output);
  const render::OutputTarget target = render::resolve_output(o.output);
  if (page) {
    write_figure_page(o, target.file);
  } else {
    const Parameters parameters = model_settings(o.model, o.settings);
    const bool mark_mesh = marks_mesh(o);
    render::Figure figure =
        o.compare.empty() ? trajectory_plot(o, parameters, mark_mesh) : comparison_plot(o, parameters);
    figure.set_transparent(o.transparent);
    figure.write(target.file);
  }
  say_wrote(o.quiet, target.shown());
}
}  // namespace

void add_plot_command(CLI::App& app) {
  auto o = std::make_shared<PlotOptions>();
  CLI::App* cmd =
      app.add_subcommand("plot", "Draw a model's solution as a figure (PNG, SVG or PDF) or an interactive page (HTML)");
  cmd->set_help_flag();  // our own help lists the model's keys
  cmd->add_flag("-h,--help", o->help, "Usage, panels and examples; with MODEL, the model's keys");
  cmd->add_option("MODEL", o->model, "Model name (vibra solve --help lists them)");
  cmd->add_option("--set", o->settings, "KEY=VALUE, repeatable (vibra plot MODEL --help lists keys)")
      ->allow_extra_args(false);
  add_output_option(*cmd, o->output, "Picture file: .png, .svg or .pdf; or .html for zoomable plots");
  cmd->add_option("--panels", o->panels, "Comma-separated panels, e.g. theta,S,D or u,exact or path");
  cmd->add_option("--compare", o->compare, "KEY=V1,V2,...: one run per value of KEY, drawn together (up to 8)")
      ->allow_extra_args(false);
  cmd->add_option("--annotate", o->annotate,
                  "mesh: a dot at every step on the time panels, the staggered scheme's v at the half steps (Fig 1.12)");
  cmd->add_option("--size", o->size, "Picture size WxH in pixels (default 1280x720, 1280x960 for 3+ panels)");
  cmd->add_flag("--transparent", o->transparent, "No background: PNG with alpha, SVG/PDF without the paper rectangle");
  add_allow_unstable_flag(*cmd);
  cmd->add_flag("-q,--quiet", o->quiet, "No message on stderr after writing");
  cmd->callback([o] { run_plot(*o); });
}

}  // namespace vibra::cli
