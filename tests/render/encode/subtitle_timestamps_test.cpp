// WebVTT cue times as HH:MM:SS.mmm to the millisecond, past a minute and an hour, against a table worked out by hand.
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "render/encode/subtitle_cue.hpp"

using vibra::render::SubtitleCue;
using vibra::render::web_vtt;

namespace {
/// The timing line of the only cue of a file holding one cue from `start` to `end`.
std::string timing_line(double start, double end) {
  const std::string vtt = web_vtt({SubtitleCue{start, end, "x"}}, "story.toml");
  const auto at = vtt.find("\n1\n");
  REQUIRE(at != std::string::npos);
  return vtt.substr(at + 3, vtt.find('\n', at + 3) - (at + 3));
}
}  // namespace

TEST_CASE("subtitle times: hours, minutes, seconds and milliseconds, each field rounded once", "[lecture][subtitles]") {
  struct Row {
    double seconds;
    const char* shown;
  };
  // Each field by hand: 3723.004 s = 1 h 2 min 3 s 4 ms; half a millisecond rounds up.
  const std::vector<Row> table = {
      {0, "00:00:00.000"},       {0.0004, "00:00:00.000"},  {0.0006, "00:00:00.001"},  {1.25, "00:00:01.250"},
      {59.9996, "00:01:00.000"}, {61.5, "00:01:01.500"},    {599.999, "00:09:59.999"},  {3599.9996, "01:00:00.000"},
      {3723.004, "01:02:03.004"}, {36000, "10:00:00.000"},  {-2, "00:00:00.000"},
  };
  for (const Row& row : table) {
    INFO(row.seconds << " s should be shown as " << row.shown);
    CHECK(timing_line(row.seconds, 90000) == std::string(row.shown) + " --> 25:00:00.000");
  }
}

TEST_CASE("subtitle cues are numbered from 1 in order, their text escaped", "[lecture][subtitles]") {
  const std::string vtt = web_vtt({{0.5, 1, "a < b & c"}, {2, 3.25, "two\n\nlines"}}, "story.toml");
  CHECK(vtt == "WEBVTT\n\nNOTE written by vibra lecture story.toml\n"
               "\n1\n00:00:00.500 --> 00:00:01.000\na &lt; b &amp; c\n"
               "\n2\n00:00:02.000 --> 00:00:03.250\ntwo\nlines\n");
}
