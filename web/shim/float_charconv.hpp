// std::to_chars and std::from_chars for double, which emscripten 3.1.6's libc++ lacks: the shortest text that reads back exactly.
#pragma once
#include <algorithm>
#include <charconv>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <system_error>

#ifdef __EMSCRIPTEN__
namespace std {

/// The shortest of %.1g ... %.17g that reads back as `value`.
inline to_chars_result to_chars(char* first, char* last, double value) {
  char text[32];
  for (int digits = 1; digits <= 17; ++digits) {
    std::snprintf(text, sizeof text, "%.*g", digits, value);
    if (std::strtod(text, nullptr) == value || digits == 17) break;
  }
  const size_t n = std::strlen(text);
  if (n > size_t(last - first)) return {last, errc::value_too_large};
  std::memcpy(first, text, n);
  return {first + n, errc()};
}

/// A decimal number at the start of [first, last), as strtod reads it.
inline from_chars_result from_chars(const char* first, const char* last, double& value) {
  char text[64];
  const size_t n = std::min<size_t>(size_t(last - first), sizeof text - 1);
  std::memcpy(text, first, n);
  text[n] = '\0';
  // from_chars takes neither a sign '+' nor leading spaces, nor hex or inf words here.
  if (n == 0 || text[0] == '+' || text[0] == ' ' || std::strpbrk(text, "xXnN")) return {first, errc::invalid_argument};
  char* end = nullptr;
  const double parsed = std::strtod(text, &end);
  if (end == text) return {first, errc::invalid_argument};
  value = parsed;
  return {first + (end - text), errc()};
}

}  // namespace std
#endif
