#pragma once
#include <CLI/CLI.hpp>
#include <functional>
#include <string>
#include <vector>

#include "cli/list_option.hpp"
#include "cli/table.hpp"
#include "render/figure.hpp"

namespace vibra::cli {

/// What every `vibra analyze` experiment offers: its table aligned or as CSV
/// on stdout, and optionally its figure.
struct AnalysisOutput {
  bool csv = false;
  std::string figure;  ///< -o FILE.png|svg|pdf; "" for none
  std::string size = "1280x720";
  bool quiet = false;  ///< no "vibra: wrote" line (and no note on stderr)
};

/// Adds --csv, -o/--output, --size and -q/--quiet to an experiment's subcommand.
void add_output_options(CLI::App&, AnalysisOutput&);

/// Checks -o and --size before the experiment runs, so a long run does not
/// end in a refused path. Throws UsageError / OutputError.
void check_output(const AnalysisOutput&);

/// Prints the table on stdout: aligned under `heading`, or as CSV.
void print_table(const AnalysisOutput&, const std::string& heading, const Table&);
/// Writes the figure `make_figure(width, height)` when -o was given.
void write_figure(const AnalysisOutput&, const std::function<render::Figure(int width, int height)>& make_figure);

}  // namespace vibra::cli
