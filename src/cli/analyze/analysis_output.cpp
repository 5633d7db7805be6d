// The options every vibra analyze experiment shares: table aligned or CSV, and an optional figure.
#include "cli/analyze/analysis_output.hpp"

#include <cstdio>

#include "cli/commands.hpp"
#include "cli/wrote_message.hpp"
#include "render/output/output_path.hpp"
#include "render/output/standard_output.hpp"

namespace vibra::cli {

void add_output_options(CLI::App& cmd, AnalysisOutput& o) {
  cmd.add_flag("--csv", o.csv, "Print the table as CSV");
  add_output_option(cmd, o.figure, "Also draw the figure: FILE.png, FILE.svg or FILE.pdf");
  cmd.add_option("--size", o.size, "Figure size WxH in pixels")->capture_default_str();
  cmd.add_flag("-q,--quiet", o.quiet, "No message on stderr after writing the figure");
}

void check_output(const AnalysisOutput& o) { app::check_figure_output(o.figure, o.size); }

void show(const AnalysisOutput& o, const app::ExperimentResult& result) {
  std::string text;
  for (size_t i = 0; i < result.tables.size(); ++i) {
    if (i) text += '\n';
    const app::TitledTable& t = result.tables[i];
    if (o.csv) {
      text += t.table.csv();
    } else {
      if (!t.heading.empty()) text += t.heading + '\n';
      text += t.table.aligned();
    }
  }
  // The conclusion goes under the table, or with --csv on stderr so that the
  // CSV stays a table (and then not with --quiet).
  if (!result.conclusion.empty() && !o.csv) text += result.conclusion + '\n';
  render::print_standard_output(text);  // a failure stops here, before the figure
  if (!result.conclusion.empty() && o.csv && !o.quiet) std::fprintf(stderr, "vibra: %s\n", result.conclusion.c_str());
  app::write_figure(result, o.figure, o.size);
  if (!o.figure.empty()) say_wrote(o.quiet, render::resolve_output(o.figure).shown());
}

}  // namespace vibra::cli
