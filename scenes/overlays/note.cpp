// Notes (--note "T0-T1: TEXT", scene key notes): text shown over a time window of a render.
#include "scenes/overlays/note.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>

#include "core/error.hpp"
#include "core/input/quoted_value.hpp"
#include "render/typeset/formula_parser.hpp"

namespace vibra::scenes {

namespace {
std::string trimmed(const std::string& s) {
  const size_t a = s.find_first_not_of(" \t"), b = s.find_last_not_of(" \t");
  return a == std::string::npos ? "" : s.substr(a, b - a + 1);
}

/// A time at `text[at]` (digits, a point, an exponent); advances `at`.
bool read_time(const std::string& text, size_t& at, double& value) {
  while (at < text.size() && text[at] == ' ') ++at;
  if (at >= text.size() || !(std::isdigit(static_cast<unsigned char>(text[at])) || text[at] == '.')) return false;
  const char* start = text.c_str() + at;
  char* end = nullptr;
  errno = 0;
  value = std::strtod(start, &end);
  if (end == start) return false;
  at += size_t(end - start);
  while (at < text.size() && text[at] == ' ') ++at;
  return true;
}
}  // namespace

Note parse_note(const std::string& spec) {
  const std::string shown = "note '" + quoted_value(spec, 60) + "'";
  const std::string example = ": write it as T0-T1: TEXT, e.g. --note \"2-4: drag takes energy out\"";
  const size_t colon = spec.find(':');
  Note note;
  size_t at = 0;
  if (colon == std::string::npos || !read_time(spec, at, note.from) || at >= colon || spec[at] != '-' ||
      !read_time(spec, ++at, note.to) || at != colon)
    throw UsageError(shown + " does not start with a time range" + example);
  if (!std::isfinite(note.from) || !std::isfinite(note.to))
    throw UsageError(shown + ": its times must be finite numbers" + example);
  if (note.to < note.from)
    throw UsageError(shown + ": it ends (t = " + short_number(note.to) + ") before it starts (t = " +
                     short_number(note.from) + "): write the earlier time first, e.g. " + short_number(note.to) + "-" +
                     short_number(note.from) + ": ...");
  std::string text = trimmed(spec.substr(colon + 1));
  // "@PANEL" as the last word points the note at that panel's curve.
  const size_t last = text.find_last_of(' ');
  const size_t word = last == std::string::npos ? 0 : last + 1;
  if (word < text.size() && text[word] == '@') {
    note.panel = text.substr(word + 1);
    if (note.panel.empty())
      throw UsageError(shown + ": '@' names no panel: write the panel after it, e.g. @theta, or drop the @");
    text = trimmed(text.substr(0, word));
  }
  if (text.empty()) throw UsageError(shown + " has no text after the colon" + example);
  try {
    (void)render::parse_rich_text(text);
  } catch (const UsageError& e) {
    throw UsageError(shown + ": " + e.what());
  }
  note.text = text;
  return note;
}

}  // namespace vibra::scenes
