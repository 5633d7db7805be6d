// End-to-end renders through the real executable: frame counts and names,
// videos read back with ffprobe and decoded, pages, stills, interrupts.
#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <thread>
#include <utility>

#include "cli_support.hpp"

using vibra::test::read_file;
using vibra::test::run_vibra;
using vibra::test::shell;
using vibra::test::ScratchDirectory;
namespace fs = std::filesystem;

namespace {
/// ffprobe's flat key=value view of the first video stream and the format.
std::string probe(const std::string& file) {
  return shell("ffprobe -v error -count_frames -select_streams v:0 -show_entries "
               "stream=codec_name,profile,pix_fmt,width,height,color_range,color_space,avg_frame_rate,nb_read_frames,duration "
               "-show_entries format=duration:format_tags=title -of flat=s=_ '" + file + "'");
}

const std::string kShortRender = " --size 320x180 --set periods=0.5 -q ";  // T = pi: 31 frames at 30 fps
}  // namespace

TEST_CASE("PNG frames: count, zero padding, and byte-identical reruns", "[render]") {
  ScratchDirectory a, b;
  REQUIRE(run_vibra("render" + kShortRender + "-o " + (a / "tmp_%04d.png")).exit_code == 0);
  REQUIRE(run_vibra("render" + kShortRender + "-o " + b.path.string()).exit_code == 0);  // a bare directory
  int count = 0, others = 0;
  for (auto& entry : fs::directory_iterator(a.path)) (entry.path().extension() == ".png" ? count : others) += 1;
  CHECK(count == 31);
  CHECK(others == 1);  // the ledger of the frames vibra wrote
  CHECK(fs::exists(a / ".vibra-frames"));
  CHECK(fs::exists(a / "tmp_0000.png"));
  CHECK(fs::exists(a / "tmp_0030.png"));
  for (const char* name : {"tmp_0000.png", "tmp_0017.png", "tmp_0030.png"}) CHECK(read_file(a / name) == read_file(b / name));
}

TEST_CASE("one frame per step follows the solver's steps", "[render]") {
  ScratchDirectory dir;
  REQUIRE(run_vibra("render pendulum_book --size 320x180 --set periods=1 -q -o " + (dir / "f_%d.png")).exit_code == 0);
  CHECK(fs::exists(dir / "f_40.png"));  // dt = 2 pi/40: 41 frames, widened to 2 digits
  CHECK(fs::exists(dir / "f_00.png"));
  CHECK(!fs::exists(dir / "f_41.png"));
}

TEST_CASE("MP4: H.264 Main, yuv420p, BT.709 tv range, exact frames and duration, faststart", "[render][video]") {
  ScratchDirectory dir;
  const std::string file = dir / "p.mp4";
  REQUIRE(run_vibra("render" + kShortRender + "-o " + file).exit_code == 0);
  const std::string p = probe(file);
  INFO(p);
  CHECK_THAT(p, Catch::Contains("codec_name=\"h264\"") && Catch::Contains("profile=\"Main\"") &&
                    Catch::Contains("pix_fmt=\"yuv420p\"") && Catch::Contains("color_range=\"tv\"") &&
                    Catch::Contains("color_space=\"bt709\"") && Catch::Contains("avg_frame_rate=\"30/1\"") &&
                    Catch::Contains("nb_read_frames=\"31\"") && Catch::Contains("title=\"vibra pendulum\""));
  CHECK_THAT(p, Catch::Contains("stream_0_duration=\"1.033333\""));  // 31 frames / 30 fps, exactly
  // Faststart: the index (moov) is a top-level box before the media data (mdat).
  const auto boxes = vibra::test::mp4_top_level_boxes(read_file(file));
  INFO("top-level boxes: " << Catch::Detail::stringify(boxes));
  const auto moov = std::find(boxes.begin(), boxes.end(), "moov"), mdat = std::find(boxes.begin(), boxes.end(), "mdat");
  REQUIRE(moov != boxes.end());
  REQUIRE(mdat != boxes.end());
  CHECK(moov < mdat);
  CHECK(shell("ffmpeg -v error -i '" + file + "' -f null - 2>&1").empty());  // every frame decodes
}

TEST_CASE("WebM: VP9 yuv420p with the right frame count", "[render][video]") {
  ScratchDirectory dir;
  const std::string file = dir / "p.webm";
  REQUIRE(run_vibra("render" + kShortRender + "-o " + file).exit_code == 0);
  const std::string p = probe(file);
  INFO(p);
  CHECK_THAT(p, Catch::Contains("codec_name=\"vp9\"") && Catch::Contains("pix_fmt=\"yuv420p\"") &&
                    Catch::Contains("nb_read_frames=\"31\"") && Catch::Contains("duration=\"1.03"));
  CHECK(shell("ffmpeg -v error -i '" + file + "' -f null - 2>&1").empty());
}

TEST_CASE("odd sizes are rounded up to even for 4:2:0, and said once", "[render][video]") {
  ScratchDirectory dir;
  const auto r = run_vibra("render --size 321x181 --set periods=0.1 -o " + (dir / "odd.mp4"));
  REQUIRE(r.exit_code == 0);
  CHECK_THAT(r.err, Catch::Contains("321x181") && Catch::Contains("322x182"));
  CHECK_THAT(probe(dir / "odd.mp4"), Catch::Contains("width=322") && Catch::Contains("height=182"));
}

TEST_CASE("other containers: mkv, ogv, gif, vp8 webm", "[render][video]") {
  ScratchDirectory dir;
  struct Case {
    const char* file;
    const char* extra;
    const char* codec;
  };
  for (const Case c : {Case{"p.mkv", "", "h264"}, {"p.ogv", "", "theora"}, {"p.gif", "", "gif"},
                       {"p8.webm", "--codec vp8", "vp8"}}) {
    INFO(c.file);
    REQUIRE(run_vibra("render" + kShortRender + c.extra + " -o " + (dir / c.file)).exit_code == 0);
    const std::string p = probe(dir / c.file);
    CHECK_THAT(p, Catch::Contains(std::string("codec_name=\"") + c.codec + "\"") && Catch::Contains("nb_read_frames=\"31\""));
  }
}

TEST_CASE("stills: PNG, SVG and PDF at a chosen time", "[render]") {
  ScratchDirectory dir;
  for (const char* name : {"s.png", "s.svg", "s.pdf"})
    REQUIRE(run_vibra("render --at 1.5 -q -o " + (dir / name)).exit_code == 0);
  CHECK(read_file(dir / "s.png").substr(1, 3) == "PNG");
  CHECK(read_file(dir / "s.svg").substr(0, 5) == "<?xml");
  CHECK(read_file(dir / "s.pdf").substr(0, 4) == "%PDF");
}

TEST_CASE("stills: --at takes an expression, as --set values do", "[render][cli]") {
  ScratchDirectory dir;
  for (const auto& [at, t] : {std::pair{"pi/2", "1.5708"}, std::pair{"2*pi", "6.28319"}}) {
    INFO("--at " << at);
    const auto r = run_vibra(std::string("render --size 320x180 --at '") + at + "' -o " + (dir / "s.png"));
    CHECK(r.exit_code == 0);
    CHECK(r.err == "vibra: wrote " + (dir / "s.png") + " (t = " + t + ")\n");
  }
}
