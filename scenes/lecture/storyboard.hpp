// Storyboard: a lecture's shots (scenes and title cards) read from a TOML file.
#pragma once
#include <optional>
#include "scenes/lecture/shot_speech.hpp"  // say, voice, audio, fit: narration
#include <string>
#include <vector>

#include "scenes/lecture/shot_ending.hpp"
#include "scenes/config/scene_config.hpp"

namespace vibra::scenes {

/// A note of a scene shot: text shown while simulated time runs from `from` to `to`.
/// One shot of a lecture: a title card, or a scene with what render accepts.
struct Shot {
  int number = 0;      ///< 1, 2, ... in the storyboard's order
  std::string title;   ///< the chapter's title: the shot's `title`, its card, or its scene
  bool is_card = false;
  ShotSpeech speech;   ///< what the shot says: flite's speech or a recorded take, and spoken notes
  bool timed = false;  ///< the storyboard gave `seconds`: speech must fit them (or fit = "stretch")
  std::string card, equation;  ///< a card's text and equation (the LaTeX subset)
  SceneConfig scene;           ///< a scene shot's scene, its keys applied
  std::optional<double> seconds;  ///< the shot's length of video; a scene shot derives its speed from it
  ShotEnding ending;   ///< presented (--present): what the shot does at its end
  std::string source;  ///< the shot as written (canonical TOML), for telling renders apart
};

/// A lecture: shots played in order into one video, all of one size and frame rate.
struct Storyboard {
  std::string file;   ///< as named, for messages
  std::string title;  ///< the lecture's title ("" = the file's stem)
  int width = 1280, height = 720;
  double fps = 30;
  std::string voice = "slt";  ///< flite's voice for shots that name none
  std::vector<Shot> shots;
};

/// Reads a storyboard file. Throws UsageError, one line naming the file,
/// the shot and the key, for unreadable or malformed TOML, an unknown key,
/// an unknown scene or a bad value; scene files named by shots are read
/// relative to the storyboard's folder.
Storyboard load_storyboard(const std::string& path);
/// A storyboard from TOML text; `file` names it in messages, `folder` is where its scene files are.
Storyboard parse_storyboard(const std::string& text, const std::string& file, const std::string& folder = "");


}  // namespace vibra::scenes
