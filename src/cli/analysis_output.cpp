#include "cli/analysis_output.hpp"

#include "cli/wrote_message.hpp"
#include "render/temporary_file.hpp"
#include "scenes/scene_config.hpp"

namespace vibra::cli {

void add_output_options(CLI::App& cmd, AnalysisOutput& o) {
  cmd.add_flag("--csv", o.csv, "Print the table as CSV");
  cmd.add_option("-o,--output", o.figure, "Also draw the figure: FILE.png, FILE.svg or FILE.pdf");
  cmd.add_option("--size", o.size, "Figure size WxH in pixels")->capture_default_str();
  cmd.add_flag("-q,--quiet", o.quiet, "No message on stderr after writing the figure");
}

void check_output(const AnalysisOutput& o) {
  int width = 0, height = 0;
  scenes::parse_size(o.size, width, height);
  if (o.figure.empty()) return;
  render::require_picture_extension(o.figure);
  const std::filesystem::path directory = std::filesystem::path(o.figure).parent_path();
  render::require_writable_directory(directory.empty() ? "." : directory);
}

void print_table(const AnalysisOutput& o, const std::string& heading, const Table& table) {
  if (o.csv) {
    table.print_csv(stdout);
  } else {
    if (!heading.empty()) std::printf("%s\n", heading.c_str());
    table.print_aligned(stdout);
  }
  std::fflush(stdout);
}

void write_figure(const AnalysisOutput& o, const std::function<render::Figure(int width, int height)>& make_figure) {
  if (o.figure.empty()) return;
  int width = 0, height = 0;
  scenes::parse_size(o.size, width, height);
  make_figure(width, height).write(o.figure);
  say_wrote(o.quiet, o.figure);
}

}  // namespace vibra::cli
