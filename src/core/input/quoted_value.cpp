// A user's value fit to quote in a one-line message: control characters escaped, long text cut.
#include "core/input/quoted_value.hpp"

#include <cstdio>

namespace vibra {

namespace {
std::string escaped(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    if (c == '\n') out += "\\n";
    else if (c == '\r') out += "\\r";
    else if (c == '\t') out += "\\t";
    else if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\x%02x", static_cast<unsigned char>(c));
      out += buf;
    } else {
      out += c;
    }
  }
  return out;
}

/// The characters a UTF-8 decoder would show: each byte that starts one,
/// and each stray continuation byte (shown as U+FFFD) on its own.
std::size_t utf8_characters(const std::string& text) {
  std::size_t characters = 0;
  int continuations_due = 0;
  for (const char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    if ((byte & 0xc0) == 0x80 && continuations_due > 0) {
      --continuations_due;
      continue;
    }
    ++characters;
    continuations_due = byte >= 0xf0 ? 3 : byte >= 0xe0 ? 2 : byte >= 0xc0 ? 1 : 0;
  }
  return characters;
}

/// Cuts `text` to about `limit` characters, keeping its head and tail, at
/// UTF-8 character boundaries.
std::string cut_middle(const std::string& text, std::size_t limit, bool say_length) {
  if (text.size() <= limit) return text;
  // Back to the byte that starts the character, at most 3 bytes back (the
  // longest UTF-8 character is 4): text that is not UTF-8 may hold a run of
  // continuation bytes as long as itself, and the cut must stay near limit.
  auto boundary = [&](std::size_t at) {
    for (int back = 0; back < 3 && at > 0 && at < text.size() && (static_cast<unsigned char>(text[at]) & 0xc0) == 0x80;
         ++back)
      --at;
    return at;
  };
  const std::size_t characters = utf8_characters(text);
  const std::string note = say_length ? "... (" + std::to_string(characters) + " characters) ..." : " ... ";
  const std::size_t keep = limit > note.size() + 8 ? limit - note.size() : 8;
  const std::size_t head = boundary(keep * 2 / 3), tail = boundary(text.size() - (keep - keep * 2 / 3));
  return text.substr(0, head) + note + text.substr(tail);
}
}  // namespace

std::string quoted_value(std::string_view text, std::size_t limit) { return cut_middle(escaped(text), limit, true); }

std::string short_number(double value) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", value);
  return buf;
}

std::string one_line_message(std::string_view message, std::size_t limit) {
  return cut_middle(escaped(message), limit, false);
}

}  // namespace vibra
