// The options every vibra analyze experiment shares: table aligned or CSV, and an optional figure.
#pragma once
#include <CLI/CLI.hpp>
#include <functional>
#include <string>
#include <vector>

#include "jobs/experiments/experiments.hpp"

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

/// Prints the experiment's tables on stdout (aligned under their headings, or
/// as CSV; a blank line between tables) and writes its figure when -o was given.
/// A failed write to stdout stops it before the figure (StandardOutputFailed).
void show(const AnalysisOutput&, const app::ExperimentResult&);

}  // namespace vibra::cli
