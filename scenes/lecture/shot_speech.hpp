// ShotSpeech: what a lecture shot says (words for flite or a recorded take, and spoken notes), as the storyboard writes it.
#pragma once
#include <string>
#include <vector>

namespace vibra::scenes {

/// A note spoken when the shot's simulated time reaches `at`.
struct SpokenNote {
  double at = 0;     ///< simulated time
  std::string text;  ///< plain words, as spoken and subtitled
  int line = 0;      ///< in the storyboard, for messages
};

/// A shot's narration. Empty: the shot is silent.
struct ShotSpeech {
  std::string say;     ///< words spoken from the shot's start (and its subtitles)
  std::string voice;   ///< flite's voice ("" = the lecture's)
  std::string audio;   ///< a recorded take played instead of flite's speech (path as read)
  bool stretch = false;  ///< fit = "stretch": a shot shorter than its speech is lengthened
  int line = 0;          ///< of `say` or `audio`, for messages
  std::vector<SpokenNote> notes;
  bool speaks() const { return !say.empty() || !audio.empty() || !notes.empty(); }
};

}  // namespace vibra::scenes
