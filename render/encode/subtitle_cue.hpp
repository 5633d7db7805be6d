// Subtitle cues and the WebVTT files vibra writes of them.
#pragma once
#include <string>
#include <vector>

namespace vibra::render {

/// A subtitle: plain text (lines joined by "\n") shown from `start` to `end`, seconds of video.
struct SubtitleCue {
  double start = 0, end = 0;
  std::string text;
};

/// The cues as a WebVTT file ("WEBVTT", then one numbered cue each, times
/// HH:MM:SS.mmm); the header's NOTE says vibra wrote it from `storyboard`
/// (as a record shows it: core/input/shown_path.hpp), which is how a later run
/// knows it may replace the file.
std::string web_vtt(const std::vector<SubtitleCue>&, const std::string& storyboard);

/// The first line of every WebVTT file vibra writes after "WEBVTT".
inline constexpr const char* kWebVttMark = "NOTE written by vibra lecture";

}  // namespace vibra::render
