// Pango's markup as runs of text, each with its style: the subset the scene code writes (i, b, sub, sup, small, span size).
#pragma once
#include <string>
#include <vector>

namespace vibra::web::shim {

/// A run's style relative to the layout's font.
struct RunStyle {
  bool italic = false, bold = false;
  double scale = 1;  ///< of the font size
  double rise = 0;   ///< baseline shift upwards, in ems of the layout's font
};

struct MarkupRun {
  std::string text;
  RunStyle style;
};

/// The runs of `markup`; throws std::invalid_argument for a tag or entity
/// outside the subset (the scene code writes none, so a test shows it).
std::vector<MarkupRun> parse_markup(const std::string& markup);

}  // namespace vibra::web::shim
