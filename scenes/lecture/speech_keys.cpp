// The storyboard's narration keys (say, voice, audio, fit, and notes spoken aloud), read into a shot's ShotSpeech.
#include "scenes/lecture/speech_keys.hpp"

#include <filesystem>

#include "core/error.hpp"
#include "render/encode/audio/audio_source.hpp"
#include "render/typeset/formula_text.hpp"
#include "scenes/overlays/note.hpp"

namespace fs = std::filesystem;

namespace vibra::scenes {

namespace {
[[noreturn]] void refuse(const std::string& where, const std::string& problem) { throw UsageError(where + ": " + problem); }

std::string words(const toml::node& value, const std::string& where, const char* example) {
  const auto text = value.value<std::string>();
  if (!value.is_string() || !text) refuse(where, std::string("must be a string, e.g. ") + example);
  if (text->find_first_not_of(" \t\r\n") == std::string::npos) refuse(where, std::string("is empty: e.g. ") + example);
  if (text->find('\0') != std::string::npos) refuse(where, "must not hold a NUL character");
  return *text;
}

/// Where a recording named relative to the storyboard is.
std::string take_path(const std::string& name, const std::string& folder) {
  return folder.empty() || fs::path(name).is_absolute() ? name : (fs::path(folder) / name).string();
}
}  // namespace

std::string read_voice(const toml::node& value, const std::string& where) {
  const std::string voice = words(value, where, "voice = \"slt\"");
  if (const std::string problem = render::voice_problem(voice); !problem.empty()) refuse(where, problem);
  return voice;
}

bool read_speech_key(ShotSpeech& speech, const std::string& key, const toml::node& value, const std::string& where,
                     const std::string& folder) {
  const int line = int(value.source().begin.line);
  if (key == "say") {
    speech.say = words(value, where, "say = \"Drag takes energy out\"");  // plain words: flite reads no math
    speech.line = speech.line ? speech.line : line;
  } else if (key == "voice") {
    speech.voice = read_voice(value, where);
  } else if (key == "audio") {
    speech.audio = take_path(words(value, where, "audio = \"takes/shot2.wav\""), folder);
    speech.line = line;
  } else if (key == "fit") {
    const std::string fit = words(value, where, "fit = \"stretch\"");
    if (fit != "stretch" && fit != "refuse")
      refuse(where, "must be \"stretch\" (a shot shorter than its speech is slowed to fit it) or \"refuse\" (the default)");
    speech.stretch = fit == "stretch";
  } else {
    return false;
  }
  return true;
}

std::string read_note_table(const toml::table& note, ShotSpeech& speech) {
  const toml::node* at = note.get("at");
  const toml::node* text = note.get("text");
  const toml::node* say = note.get("say");
  for (auto&& [key, value] : note)
    if (key.str() != "at" && key.str() != "text" && key.str() != "say")
      throw UsageError("a note takes at, text and say, not '" + std::string(key.str()) + "'");
  if (!at || !text) throw UsageError("a note needs at and text, e.g. { at = \"1-3\", text = \"...\", say = true }");
  if (say && !say->is_boolean()) throw UsageError("a note's say is true or false, e.g. say = true");
  const auto part = [](const toml::node& value, const char* example) {
    const auto words = value.value<std::string>();
    if (!value.is_string() || !words) throw UsageError(std::string("must be a string, e.g. ") + example);
    return *words;
  };
  const std::string spec = part(*at, "at = \"1-3\"") + ": " + part(*text, "text = \"...\"");
  const Note parsed = parse_note(spec);  // checks the times and the text's math
  if (say && say->value_or(false))
    speech.notes.push_back({parsed.from, render::rich_text_plain(parsed.text), int(say->source().begin.line)});
  return spec;
}

}  // namespace vibra::scenes
