// The plot job: a model's run (or one run per compared value) drawn as a static figure or a page of zoomable plots.
#pragma once
#include <string>
#include <vector>

namespace vibra::app {

/// What `vibra plot` and `vibra.plot` ask for, as text, checked by run_plot.
struct PlotRequest {
  std::string model;
  std::vector<std::string> settings;  ///< KEY=VALUE for the model
  std::string output;                 ///< FILE.png, .svg, .pdf or .html
  std::string panels;                 ///< comma-separated; empty: the model's default panels
  std::string size;                   ///< WxH; empty: 1280x720 (1280x960 for three panels or more)
  std::vector<std::string> compare;   ///< at most one KEY=V1,V2,...
  std::string annotate;               ///< "mesh" or empty
  bool transparent = false;
  std::string command_line;           ///< shown on a page
};

/// Writes the figure (or page) at request.output, put in place whole, and
/// returns its name as shown to the user. Throws UsageError for a bad
/// request, SolutionError, OutputError.
std::string run_plot(const PlotRequest& request);

}  // namespace vibra::app
