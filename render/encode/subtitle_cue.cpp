// Subtitle cues and the WebVTT files vibra writes of them.
#include "render/encode/subtitle_cue.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace vibra::render {

namespace {
std::string timestamp(double seconds) {
  const long long ms = std::llround(std::max(0.0, seconds) * 1000);
  char text[32];
  std::snprintf(text, sizeof text, "%02lld:%02lld:%02lld.%03lld", ms / 3'600'000, ms / 60'000 % 60, ms / 1000 % 60,
                ms % 1000);
  return text;
}

/// Cue text as WebVTT takes it: "-->" and blank lines would end the cue, '&' and '<' start markup.
std::string cue_text(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '&') out += "&amp;";
    else if (c == '<') out += "&lt;";
    else if (c == '>') out += "&gt;";
    else if (c == '\r') continue;
    else if (c == '\n' && (out.empty() || out.back() == '\n')) continue;
    else out += c;
  }
  while (!out.empty() && out.back() == '\n') out.pop_back();
  return out;
}
/// A file name inside the NOTE: on its line, and never "-->", which would start a cue.
std::string note_text(std::string text) {
  std::replace_if(text.begin(), text.end(), [](char c) { return c == '\n' || c == '\r'; }, ' ');
  for (std::size_t at; (at = text.find("-->")) != std::string::npos;) text.replace(at, 3, "->");  // shorter each time
  return text;
}
}  // namespace

std::string web_vtt(const std::vector<SubtitleCue>& cues, const std::string& storyboard) {
  std::string out = "WEBVTT\n\n";
  out += kWebVttMark;
  out += ' ';
  out += note_text(storyboard);
  out += "\n";
  for (std::size_t i = 0; i < cues.size(); ++i) {  // in steps: GCC 12 warns falsely about "\n" + string (bug 105329)
    out += '\n';
    out += std::to_string(i + 1);
    out += '\n';
    out += timestamp(cues[i].start) + " --> " + timestamp(cues[i].end);
    out += '\n';
    out += cue_text(cues[i].text);
    out += '\n';
  }
  return out;
}

}  // namespace vibra::render
