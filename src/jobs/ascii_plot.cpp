// vibra ascii's work: a model's trajectory streamed through the ASCII plotter.
#include "jobs/ascii_plot.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <stdexcept>

#include "core/error.hpp"
#include "core/input/quoted_value.hpp"
#include "core/models/model.hpp"
#include "render/draw/decimal_format.hpp"
#include "render/output/stop_signal.hpp"

namespace vibra::app {

int auto_plot_width(int terminal_columns) {
  return std::clamp(terminal_columns - 8, kNarrowestAutoPlot, kWidestAsciiPlot);  // 8: room for the counter
}

namespace {
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
    poll_stop(run.index());
  } while (run.index() < kPrePassSteps && run.advance());
  return largest;
}
}  // namespace

namespace {
/// The series' columns: the main quantity, or the chosen columns.
std::vector<int> plotted_columns(const TrajectoryInfo& info, const AsciiPlotOptions& o) {
  std::vector<int> columns;
  for (const auto& name : o.columns.empty() ? std::vector<std::string>{info.columns[1]} : o.columns) {
    const auto it = std::find(info.columns.begin() + 1, info.columns.end(), name);
    if (it == info.columns.end()) {
      std::string valid;
      for (size_t i = 1; i < info.columns.size(); ++i) valid += (valid.empty() ? "" : ", ") + info.columns[i];
      throw UsageError("model " + o.model + " has no column '" + name + "': choose from " + valid);
    }
    columns.push_back(static_cast<int>(it - info.columns.begin()));
  }
  return columns;
}

void check_symbols(const std::string& symbols, size_t series) {
  // A symbol is one byte of a line: 'é' (two bytes of UTF-8) would be split into invalid text.
  if (std::any_of(symbols.begin(), symbols.end(), [](unsigned char c) { return c < 0x20 || c > 0x7e; }))
    throw UsageError("--symbols '" + quoted_value(symbols, 40) + "' holds a character that is not printable ASCII: "
                     "each series is drawn with one, e.g. --symbols '*o+'");
  if (symbols.size() < series)
    throw UsageError("--symbols '" + symbols + "' has fewer symbols than the " + std::to_string(series) + " series");
}

/// The largest value the plot must hold: for the classic plot the model's
/// known amplitude (as the book's plotter); for several columns (theta, S, D
/// differ in size) the largest value of any series over a pre-pass.
double plotted_extent(Trajectory& run, const std::vector<int>& columns, const AsciiPlotOptions& o) {
  const TrajectoryInfo& info = run.info();
  double largest = 0;
  if (columns.size() == 1) {
    std::vector<double> row(run.width());
    run.row(row);
    largest = std::max(info.amplitude_bound, std::abs(row[columns[0]]));
    if (o.exact) largest = std::max(largest, std::abs(info.exact(row[0])));
  } else {
    largest = largest_value(*find_model(o.model).build(model_settings(o.model, o.settings)), columns,
                            o.exact ? info.exact : nullptr);
  }
  return !(largest > 0) || !std::isfinite(largest) ? 1 : largest;
}
}  // namespace

AsciiPlot::AsciiPlot(const AsciiPlotOptions& o) : exact_(o.exact) {
  trajectory_ = find_model(o.model).build(model_settings(o.model, o.settings));
  const TrajectoryInfo& info = trajectory_->info();
  columns_ = plotted_columns(info, o);
  if (o.exact && !info.exact)
    throw UsageError("model " + o.model + " has no exact solution with these settings: drop --exact "
                     "(undamped has one; pendulum has the small-angle one when alpha=0)");
  const size_t series = columns_.size() + (o.exact ? 1 : 0);
  check_symbols(o.symbols, series);
  row_.resize(trajectory_->width());
  values_.resize(series);
  // The range: given, or 1.2 times the extent either way of zero.
  if (o.ymin.has_value() != o.ymax.has_value()) throw UsageError("give both --ymin and --ymax, or neither");
  const double ymax = o.ymax ? *o.ymax : 1.2 * plotted_extent(*trajectory_, columns_, o);
  const double ymin = o.ymin ? *o.ymin : -ymax;
  if (o.width < 1 || o.width > kWidestAsciiPlot)
    throw UsageError("--width must be 1.." + std::to_string(kWidestAsciiPlot) + " (or auto)");
  try {
    plotter_.emplace(render::AsciiPlotterOptions{ymin, ymax, o.width, o.symbols});
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string(e.what()) + ": check --ymin, --ymax, --width and --symbols");
  }
  const std::string counter = o.counter.empty() ? (info.mesh.period > 0 ? "period" : "time") : o.counter;
  if (counter != "period" && counter != "time" && counter != "none")
    throw UsageError("--counter " + counter + " is not one of period, time, none");
  if (counter == "period" && !(info.mesh.period > 0))
    throw UsageError("model " + o.model + " has no period with these settings: use --counter time");
  show_counter_ = counter != "none";
  by_period_ = counter == "period";
  inverse_period_ = info.mesh.period > 0 ? 1 / info.mesh.period : 0;
  if (o.legend || !o.columns.empty()) {
    for (size_t i = 0; i < columns_.size(); ++i)
      legend_ += std::string(legend_.empty() ? "" : "   ") + o.symbols[i] + " " + info.columns[columns_[i]];
    if (o.exact) legend_ += std::string("   ") + o.symbols[columns_.size()] + " " + info.exact_label;
  }
}

std::string_view AsciiPlot::line() {
  trajectory_->row(row_);
  for (size_t i = 0; i < columns_.size(); ++i) values_[i] = row_[columns_[i]];
  if (exact_) values_[columns_.size()] = trajectory_->info().exact(row_[0]);
  const std::string_view plotted = plotter_->line(values_);
  if (!show_counter_) return plotted;
  line_.assign(plotted);
  char counter[330];  // format_one_decimal needs up to 320
  counter[0] = ' ';
  char* end = render::format_one_decimal(counter + 1, by_period_ ? row_[0] * inverse_period_ : row_[0]);
  line_.append(counter, end);
  return line_;
}

}  // namespace vibra::app
