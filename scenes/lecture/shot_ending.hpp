// How a presented shot ends (storyboard keys then and intro): hold its last frame, loop, or go on by itself.
#pragma once
#include <optional>
#include <string>

namespace vibra::scenes {

/// What a shot does when its video ends in a presentation (vibra lecture --present).
enum class ShotEnd { hold, loop, next };

/// A shot's `then` and `intro`: what it does at its end, and for a loop the
/// seconds of video played once before the rest loops.
struct ShotEnding {
  ShotEnd then = ShotEnd::hold;  ///< cards and scenes wait for the presenter unless told otherwise
  bool then_given = false;
  double intro = 0;  ///< seconds of video; 0: the whole shot loops
  int intro_line = 0;  ///< where intro was written, for a refusal found later (0: not given)
};

/// The word a storyboard writes for `end` ("hold", "loop", "next").
const char* shot_end_word(ShotEnd end);

/// True for the keys read_ending_key takes.
bool is_ending_key(const std::string& key);

/// A TOML value as read_ending_key needs it: its text if a string, its number if a number.
struct KeyValue {
  std::optional<std::string> text;
  std::optional<double> number;
};

/// Reads `then` or `intro` into `ending`; returns the problem ("" when fine),
/// for the storyboard to refuse at the key's line. `line` is the key's line.
std::string read_ending_key(ShotEnding& ending, const std::string& key, const KeyValue& value, int line);

/// What is wrong with the keys together ("" when nothing): an intro with
/// then = "hold" or "next", or an intro not shorter than the shot's `seconds`.
/// An intro alone makes the shot loop.
std::string settle_ending(ShotEnding& ending, std::optional<double> seconds);

}  // namespace vibra::scenes
