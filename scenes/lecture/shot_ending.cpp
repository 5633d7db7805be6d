// How a presented shot ends (storyboard keys then and intro): hold its last frame, loop, or go on by itself.
#include "scenes/lecture/shot_ending.hpp"

#include <cmath>

#include "core/input/quoted_value.hpp"

namespace vibra::scenes {

namespace {
/// The words of `then`, what each does, in the order the refusal lists them.
struct EndingWord {
  const char* word;
  ShotEnd end;
};
constexpr EndingWord kEndingWords[] = {
    {"hold", ShotEnd::hold},  // stay on the last frame until the presenter goes on
    {"loop", ShotEnd::loop},  // play again (after the intro) until the presenter goes on
    {"next", ShotEnd::next},  // go on to the next shot by itself
};
}  // namespace

const char* shot_end_word(ShotEnd end) {
  for (const EndingWord& w : kEndingWords)
    if (w.end == end) return w.word;
  return "hold";
}

bool is_ending_key(const std::string& key) { return key == "then" || key == "intro"; }

std::string read_ending_key(ShotEnding& ending, const std::string& key, const KeyValue& value, int line) {
  if (key == "then") {
    for (const EndingWord& w : kEndingWords)
      if (value.text && *value.text == w.word) {
        ending.then = w.end;
        ending.then_given = true;
        return "";
      }
    return (value.text ? "'" + quoted_value(*value.text, 40) + "' is not an ending: " : std::string()) +
           "must be \"hold\" (stay on the last frame), \"loop\" or \"next\" (go on by itself), e.g. then = \"loop\"";
  }
  if (!value.number || !(*value.number > 0) || *value.number > 3600)
    return "must be the seconds of video played once before the rest of the shot loops, above 0, e.g. intro = 2";
  ending.intro = *value.number;
  ending.intro_line = line;
  return "";
}

std::string settle_ending(ShotEnding& ending, std::optional<double> seconds) {
  if (ending.intro_line == 0) return "";
  if (!ending.then_given) ending.then = ShotEnd::loop;  // an intro is played before a loop
  if (ending.then != ShotEnd::loop)
    return std::string("is played once before a loop, but then = \"") + shot_end_word(ending.then) +
           "\": write then = \"loop\", or drop intro";
  if (seconds && !(ending.intro < *seconds))
    return "= " + short_number(ending.intro) + " leaves nothing to loop in a shot of " + short_number(*seconds) +
           " s: make it shorter than seconds";
  return "";
}

}  // namespace vibra::scenes
