// -o -: the video on standard output, raw (y4m) or encoded (NUT, Matroska),
// read back from the pipe; a reader that goes away ends the run quietly; a
// full disk behind standard output is a one-line error.
#include <algorithm>
#include <catch2/catch.hpp>
#include <string>
#include <vector>

#include "cli_support.hpp"

using vibra::test::check_refusal;
using vibra::test::run_vibra;
using vibra::test::ScratchDirectory;

namespace {
const std::string kShortToStdout = "render --size 320x180 --set periods=0.5 -q -o - ";  // 31 frames at 30 fps

std::vector<std::string> words(const std::string& text) {
  std::vector<std::string> out;
  std::size_t start = 0;
  for (std::size_t space; (space = text.find(' ', start)) != std::string::npos; start = space + 1)
    out.push_back(text.substr(start, space - start));
  out.push_back(text.substr(start));
  return out;
}
}  // namespace

TEST_CASE("standard output in y4m: a YUV4MPEG2 header and every frame", "[stream][render]") {
  const auto r = run_vibra(kShortToStdout + "--format y4m");
  REQUIRE(r.exit_code == 0);
  const std::size_t eol = r.out.find('\n');
  REQUIRE(eol != std::string::npos);
  const auto header = words(r.out.substr(0, eol));
  REQUIRE(header.size() >= 5);
  CHECK(header[0] == "YUV4MPEG2");
  CHECK(header[1] == "W320");
  CHECK(header[2] == "H180");
  CHECK(header[3] == "F30:1");
  CHECK(std::find(header.begin(), header.end(), "C420jpeg") != header.end());
  // Each frame: "FRAME\n" and 4:2:0 planes, back to back to the end.
  const std::size_t frame = 6 + 320 * 180 + 2 * 160 * 90;
  const std::size_t body = r.out.size() - (eol + 1);
  CHECK(body == 31 * frame);
  int frames = 0;
  for (std::size_t at = eol + 1; at + frame <= r.out.size(); at += frame, ++frames) REQUIRE(r.out.compare(at, 6, "FRAME\n") == 0);
  CHECK(frames == 31);
  // And FFmpeg reads it as the same 31 frames.
  ScratchDirectory dir;
  REQUIRE(run_vibra(kShortToStdout + "--format y4m > " + (dir / "x.y4m")).exit_code == 0);
  CHECK_THAT(vibra::test::shell("ffprobe -v error -count_frames -show_entries stream=codec_name,width,height,nb_read_frames,color_range "
                   "-of flat=s=_ '" + (dir / "x.y4m") + "'"),
             Catch::Contains("codec_name=\"rawvideo\"") && Catch::Contains("nb_read_frames=\"31\"") &&
                 Catch::Contains("width=320") && Catch::Contains("color_range=\"tv\""));
}

TEST_CASE("y4m at an odd size: chroma planes of the size rounded up, every frame whole", "[stream][render]") {
  // 321x181: 4:2:0 chroma is 161x91 (a half pixel more on each side), not 160x90.
  const auto r = run_vibra("render --size 321x181 --set periods=0.2 -q -o - --format y4m");
  REQUIRE(r.exit_code == 0);
  const std::size_t eol = r.out.find('\n');
  REQUIRE(eol != std::string::npos);
  const auto header = words(r.out.substr(0, eol));
  REQUIRE(header.size() >= 3);
  CHECK(header[1] == "W321");
  CHECK(header[2] == "H181");
  const std::size_t frame = 6 + 321 * 181 + 2 * 161 * 91;
  const std::size_t body = r.out.size() - (eol + 1);
  CHECK(body % frame == 0);
  CHECK(body / frame == 13);  // 0.2 of a period, played at a period in 2 s: 0.4 s at 30 fps, 13 frames
  for (std::size_t at = eol + 1; at + frame <= r.out.size(); at += frame) REQUIRE(r.out.compare(at, 6, "FRAME\n") == 0);
}

TEST_CASE("standard output in NUT or Matroska: H.264 that a pipe reader decodes", "[stream][render][video]") {
  for (const char* format : {"nut", "matroska"}) {
    INFO(format);
    ScratchDirectory dir;
    const std::string command = std::string(VIBRA_EXE) + " " + kShortToStdout + "--format " + format + " 2>" + (dir / "err") +
                                " | ffprobe -v error -count_frames -show_entries stream=codec_name,width,height,nb_read_frames "
                                "-of flat=s=_ -";
    const std::string probe = vibra::test::shell(command);
    CHECK_THAT(probe, Catch::Contains("codec_name=\"h264\"") && Catch::Contains("width=320") &&
                          Catch::Contains("nb_read_frames=\"31\""));
  }
}

TEST_CASE("a reader that closes the pipe ends the stream quietly", "[stream][render]") {
  for (const char* format : {"y4m", "nut", "matroska"}) {
    INFO(format);
    const auto ended = vibra::test::read_then_close({"render", "--size", "320x180", "--set", "periods=200", "-q", "-o", "-", "--format", format}, 1000);
    CHECK(ended.exit_code == 0);
    CHECK(ended.err.empty());
  }
}

TEST_CASE("a full disk behind standard output is a one-line error", "[stream][render]") {
  for (const char* format : {"y4m", "nut"}) {
    INFO(format);
    const auto r = run_vibra(kShortToStdout + "--format " + format + " > /dev/full");
    check_refusal(r, "No space left");
    CHECK_THAT(r.err, Catch::Contains("standard output"));
  }
}

TEST_CASE("standard output needs a stream format, and --format needs standard output", "[stream][cli]") {
  vibra::test::check_refused("render -o -", "add --format y4m");
  vibra::test::check_refused("render -o - --format webm", "--format webm is not a stream format");
  vibra::test::check_refused("render --format y4m -o OUT.mp4", "--format is for a stream (-o -, a pipe or a device)");
  vibra::test::check_refused("render -o - --format y4m --at 1", "--at renders one still");
}
