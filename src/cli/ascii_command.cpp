#include <sys/ioctl.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "cli/commands.hpp"
#include "cli/model_help.hpp"
#include "core/error.hpp"
#include "render/ascii_plotter.hpp"
#include "render/decimal_format.hpp"
#include "render/stop_signal.hpp"

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

/// The largest |value| of the given columns (and the exact solution, if
/// given) over the run, or its first kPrePassSteps steps for a longer or
/// endless one: the range then holds every series shown.
double largest_value(Trajectory& run, const std::vector<int>& columns, const std::function<double(double)>& exact) {
  constexpr long long kPrePassSteps = 1'000'000;
  std::vector<double> row(run.width());
  double largest = 0;
  do {
    run.row(row);
    for (int c : columns)
      if (std::isfinite(row[c])) largest = std::max(largest, std::abs(row[c]));
    if (exact) largest = std::max(largest, std::abs(exact(row[0])));
    if ((run.index() & 0xffff) == 0) render::throw_if_stop_requested();
  } while (run.index() < kPrePassSteps && run.advance());
  return largest;
}

void run(const AsciiOptions& o) {
  const ModelDefinition& model = find_model(o.model);
  Parameters parameters = model_settings(o.model, o.settings);
  std::unique_ptr<Trajectory> trajectory = model.build(parameters);
  const TrajectoryInfo& info = trajectory->info();

  // The series: the main quantity (or the chosen columns), then the exact solution.
  std::vector<int> columns;
  for (const auto& name : o.columns.empty() ? std::vector<std::string>{info.columns[1]} : split(o.columns)) {
    const auto it = std::find(info.columns.begin() + 1, info.columns.end(), name);
    if (it == info.columns.end()) {
      std::string valid;
      for (size_t i = 1; i < info.columns.size(); ++i) valid += (valid.empty() ? "" : ", ") + info.columns[i];
      throw UsageError("model " + o.model + " has no column '" + name + "': choose from " + valid);
    }
    columns.push_back(static_cast<int>(it - info.columns.begin()));
  }
  if (o.exact && !info.exact)
    throw UsageError("model " + o.model + " has no exact solution with these settings: drop --exact "
                     "(undamped has one; pendulum has the small-angle one when alpha=0)");
  const size_t series = columns.size() + (o.exact ? 1 : 0);
  if (o.symbols.size() < series)
    throw UsageError("--symbols '" + o.symbols + "' has fewer symbols than the " + std::to_string(series) + " series");

  std::vector<double> row(trajectory->width()), values(series);
  auto fill_values = [&] {
    for (size_t i = 0; i < columns.size(); ++i) values[i] = row[columns[i]];
    if (o.exact) values[columns.size()] = info.exact(row[0]);
  };

  // The range: given, or 1.2 times the model's known amplitude, or 1.2 times
  // the largest initial value.
  double ymin, ymax;
  if (o.ymin.has_value() != o.ymax.has_value()) throw UsageError("give both --ymin and --ymax, or neither");
  if (o.ymin) {
    ymin = *o.ymin, ymax = *o.ymax;
  } else {
    double largest = 0;
    if (columns.size() == 1) {  // the classic plot: the model's known amplitude, as the book's plotter
      trajectory->row(row);
      fill_values();
      largest = info.amplitude_bound;
      for (double v : values) largest = std::max(largest, std::abs(v));
    } else {  // several columns (theta, S, D differ in size): a pre-pass finds a range that holds them all
      largest = largest_value(*model.build(parameters), columns, o.exact ? info.exact : nullptr);
    }
    if (!(largest > 0) || !std::isfinite(largest)) largest = 1;
    ymax = 1.2 * largest, ymin = -ymax;
  }

  int width = 0;
  if (o.width == "auto") {
    width = std::max(10, terminal_columns() - 8);  // room for the counter
  } else {
    try {
      size_t used = 0;
      width = std::stoi(o.width, &used);
      if (used != o.width.size()) throw std::invalid_argument("");
    } catch (const std::exception&) {
      throw UsageError("--width " + o.width + " is not a whole number or auto");
    }
  }
  if (width < 1 || width > 10000) throw UsageError("--width must be 1..10000 (or auto)");
  std::optional<render::AsciiPlotter> plotter;
  try {
    plotter.emplace(render::AsciiPlotterOptions{ymin, ymax, width, o.symbols});
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string(e.what()) + ": check --ymin, --ymax, --width and --symbols");
  }
  const std::string counter = o.counter.empty() ? (info.mesh.period > 0 ? "period" : "time") : o.counter;
  if (counter != "period" && counter != "time" && counter != "none")
    throw UsageError("--counter " + counter + " is not one of period, time, none");
  if (counter == "period" && !(info.mesh.period > 0))
    throw UsageError("model " + o.model + " has no period with these settings: use --counter time");
  if (o.rate < 0) throw UsageError("--rate must be >= 0 lines per second");

  // Lines go through one large buffer: a terminal sees each line at once, a
  // pipe or file gets large writes.
  const bool terminal = isatty(STDOUT_FILENO) == 1;
  std::vector<char> out(1 << 16);
  size_t used = 0;
  auto flush = [&] {
    const bool ok = std::fwrite(out.data(), 1, used, stdout) == used && std::fflush(stdout) == 0;
    used = 0;
    return ok;  // false: the reader is gone (| head), so stop quietly
  };

  // A legend line (symbol and name of each series) with --columns or --legend:
  // the classic two-series run stays the book's plotter, line for line.
  if (o.legend || !o.columns.empty()) {
    std::string legend;
    for (size_t i = 0; i < columns.size(); ++i) legend += std::string(legend.empty() ? "" : "   ") + o.symbols[i] + " " + info.columns[columns[i]];
    if (o.exact) legend += std::string("   ") + o.symbols[columns.size()] + " " + info.exact_label;
    legend += '\n';
    std::memcpy(out.data(), legend.data(), std::min(legend.size(), out.size()));
    used = std::min(legend.size(), out.size());
  }
  const double inverse_period = info.mesh.period > 0 ? 1 / info.mesh.period : 0;
  const bool show_counter = counter != "none", by_period = counter == "period";
  const auto pause = std::chrono::duration<double>(o.rate > 0 ? 1 / o.rate : 0);
  do {
    if (render::stop_requested()) {  // keep the complete lines already made
      flush();
      throw render::Interrupted{render::stop_signal(), "every line written is complete"};
    }
    trajectory->row(row);
    fill_values();
    const std::string_view line = plotter->line(values);
    if (used + line.size() + 400 > out.size()) {
      if (!flush()) return;
      if (line.size() + 400 > out.size()) out.resize(line.size() + 400);
    }
    char* p = out.data() + used;
    std::memcpy(p, line.data(), line.size());
    p += line.size();
    if (show_counter) {
      *p++ = ' ';
      p = render::format_one_decimal(p, by_period ? row[0] * inverse_period : row[0]);
    }
    *p++ = '\n';
    used = p - out.data();
    if (terminal || o.rate > 0) {
      if (!flush()) return;
      if (o.rate > 0) std::this_thread::sleep_for(pause);
    }
  } while (trajectory->advance());
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
  cmd->add_flag("--exact", o->exact, "Add the exact solution as the last series");
  cmd->add_option("--columns", o->columns,
                  "Series to plot, e.g. theta,S,D (default: the main quantity); a legend line comes first, and the "
                  "default range holds every series over the run (its first million steps if longer)");
  cmd->add_flag("--legend", o->legend, "Start with a line naming each series' symbol (always with --columns)");
  cmd->add_option("--counter", o->counter, "period (t/P, one decimal), time, or none");
  cmd->add_option("--rate", o->rate, "Lines per second, to watch (the book used 10); default: as fast as it computes");
  cmd->footer(
      "\nExamples:\n  vibra ascii undamped --set scheme=euler-cromer --set T=inf --exact --width 60 --symbols +o --rate 10\n"
      "  vibra ascii pendulum --columns theta,S,D --width auto | less\n"
      "\nLine format (the classic avplotter): width+1 columns; value y at round((y - ymin)/(ymax - ymin) * width);\n"
      "later series overwrite earlier ones; '|' marks y = 0; values out of range are appended as %.1E;\n"
      "then a space and the counter.\n");
  cmd->callback([o] { run(*o); });
}

}  // namespace vibra::cli
