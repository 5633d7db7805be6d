// A run's caption (facts joined by " · ") broken onto lines and shrunk to fit a width.
#pragma once
#include <string>
#include <vector>

#include "render/draw/canvas.hpp"
#include "render/draw/text.hpp"

namespace vibra::render {

/// A run's caption (facts joined by " · ") set to fit a width: on one line
/// if it can, else broken between facts onto up to `max_lines` lines, then
/// in a smaller font (down to 80%), and only as a last resort cut short with
/// "…". A lecturer keeps every fact readable while there is room for it.
struct Caption {
  std::vector<std::string> lines;  ///< Pango markup, one entry per line
  TextStyle style;                 ///< the size chosen; max_width is the width given
  double line_height = 0;          ///< pixels
  double height() const { return line_height * double(lines.size()); }
};

/// The separator between a caption's facts.
inline constexpr const char* kCaptionSeparator = " · ";

/// Fits `markup` into `width` pixels of `canvas` (whose scale sets the font's pixels).
Caption fit_caption(Canvas&, const std::string& markup, double width, TextStyle style, int max_lines);
/// Draws the caption's lines, the last one's bottom-left corner at `bottom_left`.
void draw_caption(Canvas&, const Point& bottom_left, const Caption&);

}  // namespace vibra::render
