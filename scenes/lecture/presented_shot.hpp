// A lecture's shot rendered into a video of its own, with its first frame: what slides and a folder of shots are made of.
#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include "render/page/html_page.hpp"
#include "scenes/lecture/shot_ending.hpp"

namespace vibra::scenes {

/// One shot's own files, finished in the run's temporary folder, and what a
/// presentation shows of it.
struct PresentedShot {
  int number = 0;
  std::string title;                     ///< plain text
  std::filesystem::path video, still;    ///< the shot's video (keyframe first) and its first frame as PNG
  long long frames = 0;
  double seconds = 0;                    ///< frames / fps
  ShotEnding ending;
  std::vector<std::string> notes;        ///< for the speaker: a card's text, a scene's notes (plain text)
  /// A scene's clock: frame k shows k * interval, or time_map's pieces when paced; 0 for a card.
  double interval = 0;
  std::vector<render::PageMedia::TimePiece> time_map;
  bool sound = false;  ///< its video carries its narration (a slide then plays unmuted)
};

/// "01-drag-takes-energy-out": the shot's number (padded to the widest of
/// `shots`) and its title in lower-case ASCII letters and digits, for file
/// names that every slide program and LaTeX take.
std::string shot_file_stem(const PresentedShot& shot, std::size_t shots);

}  // namespace vibra::scenes
