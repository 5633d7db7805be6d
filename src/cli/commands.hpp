// The commands' registration functions: each adds its subcommand to the CLI11 app.
#pragma once
#include <CLI/CLI.hpp>

namespace vibra::cli {

/// Each command adds its subcommand to the app; its callback does the work
/// and throws UsageError / SolutionError / OutputError on failure.
void add_solve_command(CLI::App& app);
void add_render_command(CLI::App& app);
void add_ascii_command(CLI::App& app);
void add_plot_command(CLI::App& app);
void add_analyze_command(CLI::App& app);
void add_concat_command(CLI::App& app);
void add_lecture_command(CLI::App& app);
void add_chapter_command(CLI::App& app);

/// Thrown by a command that has said why it ends with `code` (not 0 or 2):
/// `vibra chapter --check` exits 1 when a number differs from the book's.
struct ReportedExit {
  int code;
};

/// Adds -o/--output to a command: every command's output path is given the
/// same way, and an empty one (-o '') names no file, so it is refused.
CLI::Option* add_output_option(CLI::App& cmd, std::string& path, const std::string& help);

/// Adds --allow-unstable: a dt above the scheme's stability limit is run with
/// a warning instead of refused, to draw the growth (Fig 1.5).
void add_allow_unstable_flag(CLI::App& cmd);

}  // namespace vibra::cli
