// A user's value quoted in a one-line message: escapes, and long text cut in the middle at character boundaries.
#include <catch2/catch.hpp>
#include <string>

#include "core/input/quoted_value.hpp"

using vibra::one_line_message;
using vibra::quoted_value;

TEST_CASE("a value is quoted as typed, with control characters escaped", "[quoted]") {
  CHECK(quoted_value("Theta=60") == "Theta=60");
  CHECK(quoted_value("a\nb\tc\rd\x01\x7f") == "a\\nb\\tc\\rd\\x01\\x7f");
}

TEST_CASE("a long value keeps its first two thirds and last third around its length", "[quoted]") {
  std::string digits;
  for (int i = 0; i < 100; ++i) digits += "0123456789";
  // Limit 40, a note of 25 characters: 15 kept, 10 from the start and 5 from the end.
  CHECK(quoted_value(digits) == "0123456789... (1000 characters) ...56789");
  // Two-byte characters: cut between characters, never inside one, and counted as characters.
  std::string accents;
  for (int i = 0; i < 500; ++i) accents += "é";
  CHECK(quoted_value(accents) == "ééééé... (500 characters) ...ééé");
}

TEST_CASE("a long message keeps its start (the problem) and its end (the fix) on one line", "[quoted]") {
  const std::string message = "bad value\n" + std::string(300, 'x') + " give a smaller one";
  const std::string line = one_line_message(message, 60);
  CHECK(line.size() <= 60);
  CHECK(line.find('\n') == std::string::npos);
  CHECK(line.rfind("bad value\\n", 0) == 0);
  CHECK(line.substr(line.size() - 10) == "maller one");
  CHECK(line.find(" ... ") != std::string::npos);
}

TEST_CASE("text that is not UTF-8 is cut near the limit too", "[quoted]") {
  // A run of continuation bytes with no byte to start them (as a fuzzer
  // typed): the cut looks back at most 3 bytes for a character's start,
  // so the line stays within the limit instead of keeping the whole run.
  const std::string message = "bad value " + std::string(600, '\x84') + " give a smaller one";
  const std::string line = one_line_message(message, 240);
  CHECK(line.size() <= 240);
  CHECK(line.rfind("bad value ", 0) == 0);
  CHECK(line.substr(line.size() - 10) == "maller one");
  const std::string quoted = quoted_value(std::string(1000, '\xbf'));
  CHECK(quoted.size() <= 40);
  CHECK_THAT(quoted, Catch::Contains("(1000 characters)"));  // each stray byte one, as a decoder shows it
}
