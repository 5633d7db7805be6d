// A lecture's narration: each shot's speech made before any frame, shots timed to it, and the pieces laid into one sound track.
#include "scenes/lecture/narration.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <future>
#include <thread>

#include "core/error.hpp"
#include "core/input/quoted_value.hpp"
#include "render/encode/audio/audio_source.hpp"
#include "render/output/stop_signal.hpp"

namespace vibra::scenes {

namespace {
/// "story.toml:12: shot 2, say", for messages.
std::string where(const Storyboard& board, const Shot& shot, const std::string& key, int line) {
  return board.file + (line > 0 ? ":" + std::to_string(line) : "") + ": shot " + std::to_string(shot.number) + ", " + key;
}

std::string seconds_text(double seconds) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2f s", seconds);
  return text;
}

/// The text's sentences (split after . ! ? and a space); a piece without
/// words (an ellipsis) stays with the sentence before it.
std::vector<std::string> sentences(const std::string& text) {
  std::vector<std::string> out;
  std::string current;
  const auto has_words = [](const std::string& s) {
    return std::any_of(s.begin(), s.end(), [](unsigned char c) { return std::isalnum(c); });
  };
  for (std::size_t i = 0; i < text.size(); ++i) {
    current += text[i];
    const bool end = (text[i] == '.' || text[i] == '!' || text[i] == '?') && i + 1 < text.size() &&
                     std::isspace(static_cast<unsigned char>(text[i + 1]));
    if (!end && i + 1 < text.size()) continue;
    const std::size_t first = current.find_first_not_of(" \t\r\n");
    current = first == std::string::npos ? "" : current.substr(first);
    if (!current.empty() && (has_words(current) || out.empty())) out.push_back(current);
    else if (!current.empty()) out.back() += " " + current;
    current.clear();
  }
  return out;
}

ShotNarration narrate_shot(const Storyboard& board, const Shot& shot) {
  const ShotSpeech& s = shot.speech;
  const std::string voice = s.voice.empty() ? board.voice : s.voice;
  ShotNarration n;
  try {
    double at = kSpeechLead;
    if (!s.audio.empty()) {
      n.said.push_back({at, render::read_take(s.audio), s.say});
    } else {
      for (const std::string& sentence : sentences(s.say)) {
        n.said.push_back({at, render::speak(sentence, voice), sentence});
        at += n.said.back().clip.seconds();
      }
    }
  } catch (const UsageError& e) {
    throw UsageError(where(board, shot, s.audio.empty() ? "say" : "audio", s.line) + ": " + e.what());
  }
  for (const SpokenNote& note : s.notes) {
    try {
      n.notes.push_back(render::speak(note.text, voice));
    } catch (const UsageError& e) {
      throw UsageError(where(board, shot, "notes", note.line) + ": " + e.what());
    }
  }
  return n;
}
}  // namespace

std::vector<ShotNarration> narrate_lecture(const Storyboard& board) {
  std::vector<ShotNarration> out(board.shots.size());
  const std::size_t threads = std::max(1u, std::thread::hardware_concurrency());
  for (std::size_t first = 0; first < board.shots.size(); first += threads) {  // a batch a core
    render::throw_if_stop_requested();
    std::vector<std::future<ShotNarration>> batch;
    for (std::size_t i = first; i < std::min(board.shots.size(), first + threads); ++i)
      if (board.shots[i].speech.speaks())
        batch.push_back(std::async(std::launch::async, narrate_shot, std::cref(board), std::cref(board.shots[i])));
      else
        batch.emplace_back();
    for (std::size_t i = 0; i < batch.size(); ++i)
      if (batch[i].valid()) out[first + i] = batch[i].get();
  }
  return out;
}

void fit_shots_to_speech(Storyboard& board, const std::vector<ShotNarration>& narration) {
  for (std::size_t i = 0; i < board.shots.size(); ++i) {
    Shot& shot = board.shots[i];
    const double said = narration[i].said_end();
    if (said <= 0) continue;
    const double needed = said + kSpeechTail;
    if (shot.timed && shot.seconds && *shot.seconds < said && !shot.speech.stretch)
      throw UsageError(where(board, shot, shot.speech.audio.empty() ? "say" : "audio", shot.speech.line) +
                       ": the speech lasts " + seconds_text(said) + " but the shot " + seconds_text(*shot.seconds) +
                       ": give seconds = " + short_number(std::ceil(needed * 10) / 10) +
                       " or more, say less, or add fit = \"stretch\"");
    if (shot.timed && (!shot.seconds || *shot.seconds >= said)) continue;  // speed-paced shots: checked when placed
    shot.seconds = needed;
    shot.source += "\n# timed to its speech: " + std::to_string(needed);  // a shot file of other speech is another shot
  }
}

std::vector<SpokenPiece> shot_pieces(const Storyboard& board, const Shot& shot, ShotNarration narration,
                                     const std::vector<double>& note_times, double seconds) {
  std::vector<SpokenPiece> pieces = std::move(narration.said);
  const std::string said_key = shot.speech.audio.empty() ? "say" : "audio";
  std::vector<std::string> places(pieces.size(), where(board, shot, said_key, shot.speech.line));
  for (std::size_t i = 0; i < narration.notes.size() && i < note_times.size(); ++i) {
    pieces.push_back({note_times[i], std::move(narration.notes[i]), shot.speech.notes[i].text});
    places.push_back(where(board, shot, "notes", shot.speech.notes[i].line));
  }
  std::vector<std::size_t> order(pieces.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](auto a, auto b) { return pieces[a].start < pieces[b].start; });
  std::vector<SpokenPiece> sorted;
  for (std::size_t k = 0; k < order.size(); ++k) {
    const SpokenPiece& p = pieces[order[k]];
    const double end = p.start + p.clip.seconds();
    const std::string& at = places[order[k]];
    if (!sorted.empty() && p.start < sorted.back().start + sorted.back().clip.seconds() - 1e-9)
      throw UsageError(at + ": speech from " + seconds_text(p.start) + " overlaps the speech from " +
                       seconds_text(sorted.back().start) + " to " +
                       seconds_text(sorted.back().start + sorted.back().clip.seconds()) +
                       " of the shot: move the note later or say less");
    if (end > seconds + 1e-9)
      throw UsageError(at + ": speech from " + seconds_text(p.start) + " to " + seconds_text(end) +
                       " runs past the shot's end at " + seconds_text(seconds) + ": give the shot more seconds, "
                       "speak the note earlier, or say less");
    sorted.push_back(std::move(pieces[order[k]]));
  }
  return sorted;
}

std::vector<render::SubtitleCue> speech_cues(const std::vector<SpokenPiece>& pieces) {
  std::vector<render::SubtitleCue> cues;
  for (const SpokenPiece& p : pieces)
    if (!p.text.empty()) cues.push_back({p.start, p.start + p.clip.seconds(), p.text});
  return cues;
}

render::AudioClip lecture_sound(const std::vector<const std::vector<SpokenPiece>*>& shots,
                                const std::vector<double>& shot_starts, double seconds) {
  render::AudioClip sound;
  sound.samples.assign(std::size_t(std::llround(seconds * render::AudioClip::kRate)), 0.0f);
  for (std::size_t s = 0; s < shots.size(); ++s)
    for (const SpokenPiece& p : *shots[s]) {
      const std::size_t at = std::size_t(std::llround((shot_starts[s] + p.start) * render::AudioClip::kRate));
      const std::size_t count = std::min(p.clip.samples.size(), sound.samples.size() - std::min(at, sound.samples.size()));
      std::copy_n(p.clip.samples.begin(), count, sound.samples.begin() + std::ptrdiff_t(at));
    }
  return sound;
}

std::string narration_script(const Storyboard& board, const std::vector<double>& shot_seconds) {
  std::string out = "# " + board.title + ": the narration script (vibra lecture --script)\n";
  double start = 0;
  for (std::size_t i = 0; i < board.shots.size(); ++i) {
    const Shot& shot = board.shots[i];
    char head[96];
    std::snprintf(head, sizeof head, "\nshot %d  at %d:%04.1f, %.1f s  ", shot.number, int(start) / 60,
                  start - 60 * (int(start) / 60), shot_seconds[i]);
    out += head + shot.title + "\n";
    if (!shot.speech.say.empty()) out += "  " + shot.speech.say + "\n";
    for (const SpokenNote& note : shot.speech.notes) out += "  (at t = " + short_number(note.at) + ") " + note.text + "\n";
    if (!shot.speech.speaks()) out += "  (silent)\n";
    start += shot_seconds[i];
  }
  return out;
}

}  // namespace vibra::scenes
