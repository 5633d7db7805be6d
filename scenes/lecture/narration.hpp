// A lecture's narration: each shot's speech made before any frame, shots timed to it, and the pieces laid into one sound track.
#pragma once
#include <string>
#include <vector>

#include "render/encode/audio/audio_clip.hpp"
#include "render/encode/subtitle_cue.hpp"
#include "scenes/lecture/storyboard.hpp"

namespace vibra::scenes {

/// Speech before a shot's first words and after its last (shots timed to their speech).
inline constexpr double kSpeechLead = 0.25, kSpeechTail = 0.75;  // seconds

/// A stretch of speech and the words it speaks ("" for a take without `say`).
struct SpokenPiece {
  double start = 0;  ///< seconds from the shot's start
  render::AudioClip clip;
  std::string text;
};

/// A shot's speech, made: its `say` sentence by sentence (or its take), and its spoken notes.
struct ShotNarration {
  std::vector<SpokenPiece> said;  ///< one after another from kSpeechLead
  std::vector<render::AudioClip> notes;  ///< in the order of the shot's spoken notes
  /// Seconds from the shot's start to the end of its said speech (0: none).
  double said_end() const { return said.empty() ? 0 : said.back().start + said.back().clip.seconds(); }
};

/// Every shot's speech (flite's, in the shot's voice or the lecture's, or
/// its recorded take), made on up to as many threads as cores. Throws
/// UsageError naming the file, the shot and the key for an unreadable or
/// silent take or text flite cannot speak: before any frame is drawn.
std::vector<ShotNarration> narrate_lecture(const Storyboard&);

/// Times each shot to its speech: a shot without `seconds` lasts its speech
/// and a short tail; a shot with `seconds` shorter than its speech is
/// refused with both durations, or lengthened when it says fit = "stretch".
void fit_shots_to_speech(Storyboard&, const std::vector<ShotNarration>&);

/// All of a shot's pieces in time order: its said speech, and its spoken
/// notes from `note_times` (video seconds from the shot's start, as the
/// pacing maps their simulated times). Throws UsageError with both times
/// for speech that overlaps or runs past the shot's `seconds`.
std::vector<SpokenPiece> shot_pieces(const Storyboard&, const Shot&, ShotNarration narration,
                                     const std::vector<double>& note_times, double seconds);

/// The subtitles of `pieces`: each its words, for as long as it speaks.
std::vector<render::SubtitleCue> speech_cues(const std::vector<SpokenPiece>& pieces);

/// The lecture's sound, `seconds` long: each shot's pieces from its start (`shot_starts`, seconds).
render::AudioClip lecture_sound(const std::vector<const std::vector<SpokenPiece>*>& shots,
                                const std::vector<double>& shot_starts, double seconds);

/// The narration script to record from: each shot's number, title, length and words.
std::string narration_script(const Storyboard&, const std::vector<double>& shot_seconds);

}  // namespace vibra::scenes
