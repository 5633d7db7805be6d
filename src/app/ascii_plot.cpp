#include "app/ascii_plot.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/error.hpp"
#include "core/models/model.hpp"
#include "render/decimal_format.hpp"

namespace vibra::app {

AsciiPlot::AsciiPlot(const AsciiPlotOptions& o) : exact_(o.exact) {
  trajectory_ = find_model(o.model).build(model_settings(o.model, o.settings));
  const TrajectoryInfo& info = trajectory_->info();

  // The series: the main quantity (or the chosen columns), then the exact solution.
  for (const auto& name : o.columns.empty() ? std::vector<std::string>{info.columns[1]} : o.columns) {
    const auto it = std::find(info.columns.begin() + 1, info.columns.end(), name);
    if (it == info.columns.end()) {
      std::string valid;
      for (size_t i = 1; i < info.columns.size(); ++i) valid += (valid.empty() ? "" : ", ") + info.columns[i];
      throw UsageError("model " + o.model + " has no column '" + name + "': choose from " + valid);
    }
    columns_.push_back(static_cast<int>(it - info.columns.begin()));
  }
  if (o.exact && !info.exact)
    throw UsageError("model " + o.model + " has no exact solution with these settings: drop --exact "
                     "(undamped has one; pendulum has the small-angle one when alpha=0)");
  const size_t series = columns_.size() + (o.exact ? 1 : 0);
  if (o.symbols.size() < series)
    throw UsageError("--symbols '" + o.symbols + "' has fewer symbols than the " + std::to_string(series) + " series");
  row_.resize(trajectory_->width());
  values_.resize(series);

  // The range: given, or 1.2 times the model's known amplitude, or 1.2 times
  // the largest initial value.
  double ymin, ymax;
  if (o.ymin.has_value() != o.ymax.has_value()) throw UsageError("give both --ymin and --ymax, or neither");
  if (o.ymin) {
    ymin = *o.ymin, ymax = *o.ymax;
  } else {
    trajectory_->row(row_);
    double largest = columns_.size() == 1 ? info.amplitude_bound : 0;
    for (int c : columns_) largest = std::max(largest, std::abs(row_[c]));
    if (o.exact) largest = std::max(largest, std::abs(info.exact(row_[0])));
    if (!(largest > 0)) largest = 1;
    ymax = 1.2 * largest, ymin = -ymax;
  }
  if (o.width < 1 || o.width > 10000) throw UsageError("--width must be 1..10000 (or auto)");
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

  if (series > 1) {
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
