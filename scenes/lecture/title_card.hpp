// A lecture's title card: title, text and equation drawn on a frame.
#pragma once
#include <string>

#include "render/draw/canvas.hpp"

namespace vibra::scenes {

/// What a title card shows: the lecture's title small at the top, the
/// card's text large in the middle, and its equation below.
struct TitleCard {
  std::string lecture_title;
  std::string text;      ///< the LaTeX subset: text with $math$
  std::string equation;  ///< the LaTeX subset: all math
};

/// Draws the card over the whole canvas (sizes scale with its height).
void draw_title_card(render::Canvas&, const TitleCard&);

}  // namespace vibra::scenes
