// The storyboard's narration keys (say, voice, audio, fit, and notes spoken aloud), read into a shot's ShotSpeech.
#pragma once
#include <toml++/toml.h>

#include <string>

#include "scenes/lecture/shot_speech.hpp"

namespace vibra::scenes {

/// The narration keys a shot (card or scene) takes, and the lecture's own.
inline const std::vector<std::string> kShotSpeechKeys = {"say", "voice", "audio", "fit"};
inline const std::vector<std::string> kTopSpeechKeys = {"voice"};

/// Reads `key` into `speech` when it is a narration key (true), else leaves
/// it (false). `where` is "story.toml:12: shot 2, say", for messages;
/// `folder` is where a recording's relative path starts. Throws UsageError
/// for a bad value: a voice flite lacks, an empty text, an unknown fit.
bool read_speech_key(ShotSpeech& speech, const std::string& key, const toml::node& value, const std::string& where,
                     const std::string& folder);

/// The lecture's `voice` (the default for every shot): checked at its line.
std::string read_voice(const toml::node& value, const std::string& where);

/// A note written as a table, { at = "1-3", text = "...", say = true }: its
/// "T0-T1: text" spec (as render --note takes), recorded in `speech` as
/// spoken when `say` is true. Throws UsageError (the caller names the place).
std::string read_note_table(const toml::table& note, ShotSpeech& speech);

}  // namespace vibra::scenes
