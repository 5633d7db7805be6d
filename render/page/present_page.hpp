// The presentation page: a lecture's shots as slides that wait for the presenter, with keys, loops and a speaker view.
#pragma once
#include <string>
#include <vector>

#include "render/page/html_page.hpp"

namespace vibra::render {

/// One slide: a shot's video and first frame (relative to the page), and how it ends.
struct PresentSlide {
  std::string title;
  std::string video, still;  ///< files relative to the page
  long long frames = 0;
  std::string then = "hold";  ///< "hold", "loop" or "next"
  double intro = 0;           ///< then = "loop": seconds played once before the rest loops
  std::vector<std::string> notes;  ///< for the speaker view, plain text
  /// A scene's clock for the speaker view: frame k shows k * interval, or
  /// time_map's pieces when paced; interval 0: a card, no clock.
  double interval = 0;
  std::vector<PageMedia::TimePiece> time_map;
  bool sound = false;  ///< the video speaks: played unmuted
};

/// A presentation: slides of one size and frame rate, its downloads and the command that made it.
struct Presentation {
  std::string title;
  int width = 0, height = 0;
  double fps = 30;
  std::vector<PresentSlide> slides;
  std::vector<PageDownload> downloads;
  std::string command_line;
};

/// The page as one HTML file (template render/page/present.html.in, script
/// present.js, style present.css, all compiled in: no network).
std::string presentation_html(const Presentation&);

}  // namespace vibra::render
