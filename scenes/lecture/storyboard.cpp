// Storyboard: a lecture's shots (scenes and title cards) read from a TOML file.
#include "scenes/lecture/storyboard.hpp"

#include <toml++/toml.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "core/error.hpp"
#include "core/input/input_files.hpp"
#include "core/input/parameters.hpp"
#include "core/input/quoted_value.hpp"
#include "render/typeset/formula_parser.hpp"
#include "render/typeset/formula_text.hpp"
#include "scenes/overlays/note.hpp"
#include "scenes/lecture/speech_keys.hpp"
#include "scenes/config/scene_table.hpp"

namespace fs = std::filesystem;

namespace vibra::scenes {

namespace {
constexpr double kLongestShot = 3600;  ///< seconds of video
constexpr std::size_t kMostShots = 1000;

const std::vector<std::string> kTopKeys = {"title", "size", "fps", "shot"};
const std::vector<std::string> kCardKeys = {"card", "equation", "seconds", "title",
                                           "then", "intro"};  // then, intro: presenting (shot_ending.hpp)
const std::vector<std::string> kShotKeys = {"scene", "set", "seconds", "notes", "title",
                                           "then", "intro"};
/// The scene keys that pace a shot by a speed, as `seconds` would by a
/// length: not both. video_speed is speed's name for models with a key
/// speed of their own. (frame_per_step paces too, when true.)
const std::vector<std::string> kSpeedKeys = {"speed", "video_speed"};

/// Where a value sits: "story.toml:12: shot 2, key" (line 0: unknown).
struct Place {
  const std::string& file;
  int shot;
  std::string key;
  int line;
  std::string text() const {
    std::string out = file + (line > 0 ? ":" + std::to_string(line) : "");
    if (shot > 0) out += ": shot " + std::to_string(shot);
    return out + (key.empty() ? "" : (shot > 0 ? ", " : ": ") + key);
  }
  [[noreturn]] void refuse(const std::string& problem) const { throw UsageError(text() + ": " + problem); }
};

std::string list_of(const std::vector<std::string>& words) {
  std::string out;
  for (const auto& w : words) out += (out.empty() ? "" : ", ") + w;
  return out;
}

std::string text_value(const toml::node& node, const Place& at) {
  if (!node.is_string()) at.refuse("must be a string, e.g. " + at.key + " = \"...\"");
  std::string text = *node.value<std::string>();
  if (text.find('\0') != std::string::npos) at.refuse("must not hold a NUL character");
  return text;
}

double seconds_value(const toml::node& node, const Place& at) {
  const auto value = node.value<double>();
  if (!(node.is_integer() || node.is_floating_point()) || !value || !(*value > 0) || *value > kLongestShot)
    at.refuse("must be a number of seconds above 0 and at most 3600, e.g. seconds = 6");
  return *value;
}

/// A key the shot may not have: names the keys it may.
[[noreturn]] void refuse_key(const Place& at, const std::vector<std::string>& allowed, const std::string& kind) {
  std::vector<std::string> candidates = allowed;
  const std::vector<std::string>& spoken = allowed == kTopKeys ? kTopSpeechKeys : kShotSpeechKeys;
  candidates.insert(candidates.end(), spoken.begin(), spoken.end());
  const std::string near = closest_match(at.key, candidates);
  at.refuse("is not a key of " + kind + (near.empty() ? "" : " (did you mean '" + near + "'?)") + ": it takes " +
            list_of(candidates));
}

/// A key list with the narration keys (speech_keys.hpp) added.
std::vector<std::string> with_speech_keys(std::vector<std::string> keys) {
  keys.insert(keys.end(), kShotSpeechKeys.begin(), kShotSpeechKeys.end());
  return keys;
}

/// A shot's then or intro (how it ends when presented), refused at its line.
void ending_value(Shot& shot, const toml::node& node, const Place& at) {
  const KeyValue value{node.value<std::string>(),
                       node.is_integer() || node.is_floating_point() ? node.value<double>() : std::nullopt};
  const std::string problem = read_ending_key(shot.ending, at.key, value, at.line);
  if (!problem.empty()) at.refuse(problem);
}

/// The shot's then and intro checked together, at intro's line.
void settle_shot_ending(Shot& shot, const std::string& file) {
  const std::string problem = settle_ending(shot.ending, shot.seconds);
  if (!problem.empty()) Place{file, shot.number, "intro", shot.ending.intro_line}.refuse(problem);
}

std::string source_text(const toml::table& shot) {
  std::ostringstream out;
  out << shot;
  return out.str();
}

/// The first line of a card's text, for its chapter title.
std::string first_line(const std::string& text) { return text.substr(0, text.find('\n')); }

/// A text value that vibra typesets: a formula (`math`) or text with $math$,
/// checked here so that bad LaTeX is refused at its line before any work.
std::string typeset_value(const toml::node& node, const Place& at, bool math) {
  std::string text = text_value(node, at);
  try {
    if (math) render::parse_formula(text);
    else render::parse_rich_text(text);
  } catch (const UsageError& e) {
    at.refuse(e.what());
  }
  return text;
}

Shot card_shot(const toml::table& table, const std::string& file, const std::string& folder, int number) {
  Shot shot;
  shot.number = number;
  shot.is_card = true;
  shot.timed = table.contains("seconds");
  for (auto&& [key, node] : table) {
    const Place at{file, number, std::string(key.str()), int(node.source().begin.line)};
    if (read_speech_key(shot.speech, at.key, node, at.text(), folder)) continue;
    if (at.key == "card") shot.card = typeset_value(node, at, false);
    else if (at.key == "equation") shot.equation = typeset_value(node, at, true);
    else if (at.key == "title") shot.title = render::rich_text_plain(typeset_value(node, at, false));
    else if (at.key == "seconds") shot.seconds = seconds_value(node, at);
    else if (is_ending_key(at.key)) ending_value(shot, node, at);
    else refuse_key(at, kCardKeys, "a title card (a scene key belongs to a shot with scene = ...)");
  }
  if (shot.card.empty() && shot.equation.empty())
    Place{file, number, "card", 0}.refuse("is empty: give the card's text, e.g. card = \"The damped pendulum\"");
  if (shot.title.empty())
    shot.title = first_line(shot.card.empty() ? render::formula_plain_text(shot.equation)
                                              : render::rich_text_plain(shot.card));
  if (!shot.seconds) shot.seconds = 3;
  settle_shot_ending(shot, file);
  return shot;
}

/// The scene a shot names: a built-in scene, a model, or a scene file
/// (relative to the storyboard's folder when it is there).
SceneConfig shot_scene(const std::string& name, const std::string& folder, const Place& at) {
  std::string path = name;
  std::error_code ec;
  if (!folder.empty() && fs::path(name).is_relative() && fs::is_regular_file(fs::path(folder) / name, ec))
    path = (fs::path(folder) / name).string();
  try {
    return load_scene(path);
  } catch (const UsageError& e) {
    at.refuse(e.what());
  }
}

Shot scene_shot(const toml::table& table, const std::string& file, const std::string& folder, int number) {
  Shot shot;
  shot.number = number;
  shot.timed = table.contains("seconds") || table.contains("frame_per_step") ||
               std::any_of(kSpeedKeys.begin(), kSpeedKeys.end(), [&](const std::string& key) { return table.contains(key); });
  const toml::node* scene = table.get("scene");
  const Place scene_at{file, number, "scene", scene ? int(scene->source().begin.line) : 0};
  if (!scene)
    scene_at.refuse("is missing: a shot is a card (card = \"...\") or a scene (scene = \"pendulum\", or a scene file)");
  shot.scene = shot_scene(text_value(*scene, scene_at), folder, scene_at);
  const std::string where = "shot " + std::to_string(number);
  std::vector<const toml::table*> model_keys;
  for (auto&& [key, node] : table) {
    const Place at{file, number, std::string(key.str()), int(node.source().begin.line)};
    if (at.key == "scene" || read_speech_key(shot.speech, at.key, node, at.text(), folder)) continue;
    if (at.key == "title") shot.title = render::rich_text_plain(typeset_value(node, at, false));
    else if (at.key == "seconds") shot.seconds = seconds_value(node, at);
    else if (is_ending_key(at.key)) ending_value(shot, node, at);
    else if (at.key == "set") {
      if (!node.is_table()) at.refuse("must be a table of keys, e.g. set = { Theta = 40, alpha = 0.8 }");
      model_keys.push_back(node.as_table());
    } else if (at.key == "notes") {
      const toml::array* notes = node.as_array();
      if (!notes) at.refuse("must be a list of \"T0-T1: text\", e.g. notes = [\"2-4: drag takes energy out\"]");
      for (const toml::node& note : *notes) {
        try {
          // A note is the scene's callout (render --note); a subtitle only when no frame shows it.
          const std::string spec = note.is_table() ? read_note_table(*note.as_table(), shot.speech)
                                                   : text_value(note, at);
          (void)parse_note(spec);
          shot.scene.notes.push_back(spec);
        } catch (const UsageError& e) {
          at.refuse(e.what());
        }
      }
    } else if (at.key == "size" || at.key == "fps") {
      at.refuse("is the lecture's, not a shot's: set it once at the top of the file (every shot has one size and fps)");
    } else if (at.key == "card" || at.key == "equation") {
      at.refuse("belongs to a title card, not a scene shot: put it in a shot of its own");
    }
  }
  const std::vector<Setting> settings = table_settings(table, file, where, with_speech_keys(kShotKeys));  // the scene keys
  for (const Setting& s : settings)  // the model first: the other keys are checked against it
    if (s.key == "model") apply_setting(shot.scene, s);
  for (const Setting& s : settings)
    if (s.key != "model") apply_setting(shot.scene, s);
  for (const toml::table* set : model_keys)
    for (const Setting& s : table_settings(*set, file, where)) apply_setting(shot.scene, s);
  for (const std::string& speed : kSpeedKeys)
    if (shot.seconds && table.get(speed))
      Place{file, number, "seconds", 0}.refuse("and " + speed + " both set the shot's pace: give one of them");
  if (shot.seconds && shot.scene.frame_per_step)
    Place{file, number, "seconds", 0}.refuse("and frame_per_step both set the shot's pace: give one of them");
  if (shot.title.empty()) shot.title = shot.scene.name + (shot.scene.compare.empty() ? "" : ": " + shot.scene.compare);
  settle_shot_ending(shot, file);
  return shot;
}
}  // namespace

Storyboard parse_storyboard(const std::string& text, const std::string& file, const std::string& folder) {
  if (text.find('\0') != std::string::npos) throw UsageError(file + ": is a binary file, not a TOML storyboard");
  toml::table table;
  try {
    table = toml::parse(text, file);
  } catch (const toml::parse_error& e) {
    throw UsageError(file + ":" + std::to_string(e.source().begin.line) + ": " + std::string(e.description()) +
                     " (a storyboard is TOML: title = \"...\", then [[shot]] tables)");
  }
  refuse_long_keys(table, file);
  Storyboard board;
  board.file = file;
  board.title = fs::path(file).stem().string();
  for (auto&& [key, node] : table) {
    const Place at{file, 0, std::string(key.str()), int(node.source().begin.line)};
    if (at.key == "title") {
      board.title = typeset_value(node, at, false);
    } else if (at.key == "size") {
      try {
        parse_size(text_value(node, at), board.width, board.height);
      } catch (const UsageError& e) {
        at.refuse(e.what());
      }
    } else if (at.key == "fps") {
      const auto fps = node.value<double>();
      if (!fps || !(*fps >= 1 && *fps <= 240) || *fps != std::floor(*fps))
        at.refuse("must be a whole number of frames per second, 1..240, e.g. fps = 30");
      board.fps = *fps;
    } else if (at.key == "voice") {
      board.voice = read_voice(node, at.text());
    } else if (at.key != "shot") {
      refuse_key(at, kTopKeys, "a storyboard");
    }
  }
  const toml::node* shots = table.get("shot");
  const toml::array* list = shots ? shots->as_array() : nullptr;
  if (!list || list->empty())
    Place{file, 0, "shot", 0}.refuse("no shots: add [[shot]] tables, e.g. [[shot]] card = \"Title\", or scene = \"pendulum\"");
  if (list->size() > kMostShots) Place{file, 0, "shot", 0}.refuse("more than 1000 shots: split the lecture");
  int number = 0;
  for (const toml::node& node : *list) {
    ++number;
    const toml::table* shot = node.as_table();
    if (!shot) Place{file, number, "", int(node.source().begin.line)}.refuse("is not a table: write [[shot]] and its keys");
    Shot s = shot->contains("card") || shot->contains("equation") ? card_shot(*shot, file, folder, number)
                                                                   : scene_shot(*shot, file, folder, number);
    s.scene.width = board.width, s.scene.height = board.height, s.scene.fps = board.fps;
    s.source = source_text(*shot);
    board.shots.push_back(std::move(s));
  }
  return board;
}

Storyboard load_storyboard(const std::string& path) {
  std::error_code ec;
  if (!fs::is_regular_file(path, ec))
    throw UsageError("no storyboard '" + quoted_value(path, 80) + "': give a TOML file of [[shot]] tables "
                     "(docs/lecture.md has an example)");
  return parse_storyboard(read_input_file(path, "the storyboard", "the storyboard", kMostSettingsBytes), path, fs::path(path).parent_path().string());
}

}  // namespace vibra::scenes
