// vibra ascii's work: a model's trajectory streamed through the ASCII plotter.
#pragma once
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/trajectory.hpp"
#include "render/plot/ascii_plotter.hpp"

namespace vibra::app {

/// The widest plot (columns - 1) and the narrowest --width auto gives.
inline constexpr int kWidestAsciiPlot = 10000, kNarrowestAutoPlot = 10;

/// --width auto: the terminal's columns less room for the counter, clamped to
/// what a plot may be (a 65535-column terminal gets the widest plot).
int auto_plot_width(int terminal_columns);

struct AsciiPlotOptions {
  std::string model;
  std::vector<std::string> settings;  ///< KEY=VALUE for the model (T=inf runs until stopped)
  int width = 68;                     ///< plot columns - 1, 1..10000
  std::string symbols = "*o+x@";     ///< one printable ASCII character per series
  /// Both or neither; default: 1.2 times the known amplitude for one column,
  /// 1.2 times the largest value of every series shown for several.
  std::optional<double> ymin, ymax;
  bool exact = false;                ///< add the exact solution as the last series
  std::string counter;               ///< period | time | none; "" = period when the model has one
  std::vector<std::string> columns;  ///< series to plot; empty = the main quantity
  /// Start with a legend line (always with `columns`): the classic run, one
  /// column with or without the exact solution, stays the book's plotter
  /// line for line.
  bool legend = false;
};

/// A run plotted line by line as text (`vibra ascii`, `vibra.ascii_lines`):
/// one line per time step, the plotter's line followed by the counter, in
/// constant memory for as long as the run goes.
class AsciiPlot {
 public:
  /// Builds the model's trajectory and checks the options; throws UsageError
  /// naming the option and the fix (in the command line's words).
  explicit AsciiPlot(const AsciiPlotOptions&);

  /// Symbol and name of each series, e.g. "* u   o exact"; "" unless
  /// AsciiPlotOptions::legend or columns asked for it.
  const std::string& legend() const { return legend_; }
  /// The current sample's line with its counter, without a newline; valid
  /// until the next call.
  std::string_view line();
  /// Moves to the next time step; false at the end. Throws SolutionError.
  bool advance() { return trajectory_->advance(); }

 private:
  std::unique_ptr<Trajectory> trajectory_;
  std::vector<int> columns_;
  bool exact_;
  std::optional<render::AsciiPlotter> plotter_;
  std::vector<double> row_, values_;
  std::string legend_, line_;
  bool show_counter_, by_period_;
  double inverse_period_;
};

}  // namespace vibra::app
