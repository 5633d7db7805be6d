// Registers vibra plot: a static figure of a run's panels.
#include <memory>
#include <string>
#include <vector>

#include "cli/command_line.hpp"
#include "cli/commands.hpp"
#include "cli/manuals/model_help.hpp"
#include "cli/wrote_message.hpp"
#include "core/error.hpp"
#include "jobs/plot_job.hpp"

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

void run_plot_command(const PlotOptions& o) {
  if (o.help || o.model.empty()) {
    print_model_help(std::string(kUsage) + kExamples + "\n", o.model);
    if (!o.help) throw UsageError("vibra plot needs a MODEL, e.g. vibra plot pendulum -o pendulum.png");
    return;
  }
  const app::PlotRequest request{o.model, o.settings, o.output,      o.panels,     o.size,
                                 o.compare, o.annotate, o.transparent, command_line()};
  say_wrote(o.quiet, app::run_plot(request));
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
  cmd->callback([o] { run_plot_command(*o); });
}

}  // namespace vibra::cli
