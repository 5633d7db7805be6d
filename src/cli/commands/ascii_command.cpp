// Registers vibra ascii: a model's trajectory as the classic ASCII plot on standard output.
#include <sys/ioctl.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <memory>
#include <optional>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "jobs/ascii_plot.hpp"
#include "cli/commands.hpp"
#include "cli/option_checks.hpp"
#include "core/error.hpp"
#include "render/output/standard_output.hpp"
#include "render/output/stop_signal.hpp"

namespace vibra::cli {

namespace {
struct AsciiOptions {
  std::string model;
  std::vector<std::string> settings;
  std::string width = "68";
  std::string symbols = "*o+x@";
  std::optional<double> ymin, ymax;
  bool exact = false;
  std::string counter;  ///< period | time | none; "" = period when the model has one
  double rate = 0;
  std::string columns;
  bool legend = false;
};

/// Splits "a,b,c".
std::vector<std::string> split(const std::string& list) {
  std::vector<std::string> out;
  size_t start = 0;
  for (size_t comma; (comma = list.find(',', start)) != std::string::npos; start = comma + 1)
    out.push_back(list.substr(start, comma - start));
  out.push_back(list.substr(start));
  return out;
}

int terminal_columns() {
  winsize size{};
  if (ioctl(STDOUT_FILENO, TIOCGWINSZ, &size) == 0 && size.ws_col > 0) return size.ws_col;
  return 80;
}

void run(const AsciiOptions& o) {
  app::AsciiPlotOptions plot_options;
  plot_options.model = o.model;
  plot_options.settings = o.settings;
  if (o.width == "auto") {
    plot_options.width = app::auto_plot_width(terminal_columns());
  } else {
    try {
      size_t used = 0;
      plot_options.width = std::stoi(o.width, &used);
      if (used != o.width.size()) throw std::invalid_argument("");
    } catch (const std::exception&) {
      throw UsageError("--width " + o.width + " is not a whole number or auto");
    }
  }
  plot_options.symbols = o.symbols;
  plot_options.ymin = o.ymin;
  plot_options.ymax = o.ymax;
  plot_options.exact = o.exact;
  plot_options.counter = o.counter;
  if (!o.columns.empty()) plot_options.columns = split(o.columns);
  plot_options.legend = o.legend;
  app::AsciiPlot plot(plot_options);
  if (o.rate < 0) throw UsageError("--rate must be >= 0 lines per second");

  // Lines go through one large buffer: a terminal sees each line at once, a
  // pipe or file gets large writes.
  const bool terminal = isatty(STDOUT_FILENO) == 1;
  std::vector<char> out(1 << 16);
  size_t used = 0;
  auto flush = [&] {  // a failed write (the reader gone, a full disk) ends the run: StandardOutputFailed
    const size_t size = std::exchange(used, 0);
    render::print_standard_output({out.data(), size});
  };

  if (!plot.legend().empty()) {
    const std::string legend = plot.legend() + '\n';
    std::memcpy(out.data(), legend.data(), std::min(legend.size(), out.size()));
    used = std::min(legend.size(), out.size());
  }
  const auto pause = std::chrono::duration<double>(o.rate > 0 ? 1 / o.rate : 0);
  do {
    if (render::stop_requested()) {  // keep the complete lines already made
      try {
        flush();
      } catch (const render::StandardOutputFailed&) {  // recorded; the interrupt is the one line to say
      }
      throw render::Interrupted{render::stop_signal(), "every line written is complete"};
    }
    const std::string_view line = plot.line();
    if (used + line.size() + 1 > out.size()) {
      flush();
      if (line.size() + 1 > out.size()) out.resize(line.size() + 1);
    }
    std::memcpy(out.data() + used, line.data(), line.size());
    used += line.size();
    out[used++] = '\n';
    if (terminal || o.rate > 0) {
      flush();
      if (o.rate > 0) std::this_thread::sleep_for(pause);
    }
  } while (plot.advance());
  flush();
}
}  // namespace

void add_ascii_command(CLI::App& app) {
  auto o = std::make_shared<AsciiOptions>();
  CLI::App* cmd = app.add_subcommand("ascii", "Plot a run line by line as text, in constant memory, for as long as it runs");
  cmd->add_option("MODEL", o->model, "Model name (vibra solve --help lists them)")->required();
  cmd->add_option("--set", o->settings, "KEY=VALUE for the model (T=inf runs until interrupted)");
  cmd->add_option("--width", o->width, "Plot columns - 1, or auto for the terminal's width")->capture_default_str();
  cmd->add_option("--symbols", o->symbols, "Symbols of the series, in order; later ones draw on top")->capture_default_str();
  cmd->add_option("--ymin", o->ymin, "Lower end of the y axis (with --ymax)");
  cmd->add_option("--ymax", o->ymax, "Upper end of the y axis (with --ymin)");
  add_allow_unstable_flag(*cmd);
  cmd->add_flag("--exact", o->exact, "Add the exact solution as the last series");
  cmd->add_option("--columns", o->columns,
                  "Series to plot, e.g. theta,S,D (default: the main quantity); a legend line comes first, and the "
                  "default range holds every series over the run (its first million steps if longer)");
  cmd->add_flag("--legend", o->legend, "Start with a line naming each series' symbol (always with --columns)");
  cmd->add_option("--counter", o->counter, "period (t/P, one decimal), time, or none");
  cmd->add_option("--rate", o->rate, "Lines per second, to watch (the book used 10); default: as fast as it computes")
      ->check(ranged("--rate"));
  cmd->footer(
      "\nExamples:\n  vibra ascii undamped --set scheme=euler-cromer --set T=inf --exact --width 60 --symbols +o --rate 10\n"
      "  vibra ascii pendulum --columns theta,S,D --width auto | less\n"
      "\nLine format (the classic avplotter): width+1 columns; value y at round((y - ymin)/(ymax - ymin) * width);\n"
      "later series overwrite earlier ones; '|' marks y = 0; values out of range are appended as %.1E;\n"
      "then a space and the counter.\n");
  cmd->callback([o] { run(*o); });
}

}  // namespace vibra::cli
