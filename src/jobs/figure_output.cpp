// Writes an experiment's figure to the path the user gave, through a temporary file.
#include <filesystem>

#include "jobs/experiments/experiments.hpp"
#include "render/output/output_path.hpp"
#include "render/plot/figure.hpp"
#include "scenes/config/scene_config.hpp"

namespace vibra::app {

void check_figure_output(const std::string& figure, const std::string& size) {
  int width = 0, height = 0;
  scenes::parse_size(size, width, height);
  if (figure.empty()) return;
  render::require_picture_extension(figure);
  render::resolve_output(figure);  // before the experiment: a folder there, a file in the way
}

void write_figure(const ExperimentResult& result, const std::string& figure, const std::string& size) {
  if (figure.empty()) return;
  int width = 0, height = 0;
  scenes::parse_size(size, width, height);
  result.figure(width, height).write(figure);
}

}  // namespace vibra::app
