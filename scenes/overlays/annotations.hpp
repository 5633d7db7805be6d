// The marks of the book's figures that --annotate NAME adds, and which command (render or plot) draws each.
#pragma once
#include <string>
#include <vector>

namespace vibra::scenes {

/// A mark of one of the book's figures that `--annotate NAME` adds, and the
/// command that draws it: a diagram's (render) or a figure's (plot).
struct AnnotationKind {
  std::string name;
  std::string command;  ///< "render" or "plot"
  std::string summary;  ///< what it draws, for help
  std::string example;  ///< a command that draws it, for errors
};

/// Every annotation: geometry (render, Fig 1.21) and mesh (plot, Fig 1.12).
const std::vector<AnnotationKind>& all_annotations();

/// Throws UsageError unless `command` draws the annotation `name`: an unknown
/// name gets the closest one and the list, a known one the command that draws it.
void check_annotation_name(const std::string& name, const std::string& command);

}  // namespace vibra::scenes
