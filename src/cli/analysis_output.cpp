#include "cli/analysis_output.hpp"

#include <cstdio>

#include "cli/wrote_message.hpp"

namespace vibra::cli {

void add_output_options(CLI::App& cmd, AnalysisOutput& o) {
  cmd.add_flag("--csv", o.csv, "Print the table as CSV");
  cmd.add_option("-o,--output", o.figure, "Also draw the figure: FILE.png, FILE.svg or FILE.pdf");
  cmd.add_option("--size", o.size, "Figure size WxH in pixels")->capture_default_str();
  cmd.add_flag("-q,--quiet", o.quiet, "No message on stderr after writing the figure");
}

void check_output(const AnalysisOutput& o) { app::check_figure_output(o.figure, o.size); }

void show(const AnalysisOutput& o, const app::ExperimentResult& result) {
  for (size_t i = 0; i < result.tables.size(); ++i) {
    if (i) std::printf("\n");
    const app::TitledTable& t = result.tables[i];
    if (o.csv) {
      t.table.print_csv(stdout);
    } else {
      if (!t.heading.empty()) std::printf("%s\n", t.heading.c_str());
      t.table.print_aligned(stdout);
    }
  }
  // The conclusion goes under the table, or with --csv on stderr so that the
  // CSV stays a table (and then not with --quiet).
  if (!result.conclusion.empty() && !(o.csv && o.quiet)) {
    std::FILE* stream = o.csv ? stderr : stdout;
    std::fprintf(stream, "%s%s\n", o.csv ? "vibra: " : "", result.conclusion.c_str());
  }
  std::fflush(stdout);
  app::write_figure(result, o.figure, o.size);
  if (!o.figure.empty()) say_wrote(o.quiet, o.figure);
}

}  // namespace vibra::cli
