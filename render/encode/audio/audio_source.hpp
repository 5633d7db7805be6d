// Speech from flite and recorded takes, made in process through a libavfilter graph into 48 kHz mono clips.
#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include "render/encode/audio/audio_clip.hpp"

namespace vibra::render {

/// flite's voices in Debian's build; the first, slt, is the clearest of them.
const std::vector<std::string>& speech_voices();
/// "" when `voice` is one of speech_voices(); else why not, naming them.
std::string voice_problem(const std::string& voice);

/// `text` spoken by flite's `voice`, resampled to 48 kHz and brought to
/// about -16 LUFS (loudness.hpp). Throws UsageError when the voice is
/// unknown or flite speaks nothing of the text (no words in it).
AudioClip speak(const std::string& text, const std::string& voice);

/// A recording (WAV, FLAC, MP3, Opus: whatever libavformat reads), mixed down
/// to mono and resampled to 48 kHz, its samples otherwise unchanged. Throws
/// UsageError naming the file when it cannot be read, holds no sound, or
/// lasts more than an hour.
AudioClip read_take(const std::filesystem::path& file);

}  // namespace vibra::render
