// Slow motion and pauses in a render: the video grows by what the pacing
// adds, each frame is the still at its simulated time, a paused frame is the
// same picture, and the lecture page maps the video's time through the same
// pieces (page.js evaluated by node against the render's own clock).
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <regex>
#include <string>
#include <utility>
#include <vector>

#include "cli_support.hpp"
#include "png_compare.hpp"
#include "scenes/timing/frame_clock.hpp"
#include "scenes/timing/pacing.hpp"

using vibra::test::exact_text;
using vibra::test::check_refused;
using vibra::test::psnr;
using vibra::test::read_file;
using vibra::test::run_vibra;
using vibra::test::ScratchDirectory;
using vibra::test::shell;
namespace fs = std::filesystem;

namespace {

long long count_files(const fs::path& dir, const std::string& prefix) {
  long long n = 0;
  for (const auto& e : fs::directory_iterator(dir)) n += e.path().filename().string().rfind(prefix, 0) == 0;
  return n;
}

std::string frame_name(const ScratchDirectory& dir, long long k) {
  char name[32];
  std::snprintf(name, sizeof name, "f_%04lld.png", k);
  return dir / name;
}

vibra::scenes::Pacing pacing(const char* slow, const char* pause) {
  vibra::scenes::Pacing p;
  if (slow) p.add_slow(slow);
  if (pause) p.add_pause(pause);
  return p;
}
}  // namespace

TEST_CASE("slow motion and pauses: frame counts, frames equal to stills, paused frames the same picture",
          "[pacing][frame-truth]") {
  struct Case {
    std::string scene;
    double T, fps, speed;
    const char *slow, *pause;
    std::vector<long long> ks;
  };
  const std::vector<Case> cases = {
      {"spring --size 320x180 --set dt=0.05", 4, 10, 1, "1-2:4", "3:1", {5, 12, 27, 47, 51, 55, 62}},
      {"pendulum --size 320x180 --set T=6", 6, 30, 2, "1-3:3", "4.5:0.5", {10, 31, 70, 100, 118, 130}},
      {"spring --size 320x180 --set dt=0.05", 4, 10, 1, "0-4:0.5", "0:0.5", {0, 3, 6, 9, 12}},  // faster, held at t = 0
  };
  for (const Case& c : cases) {
    const std::string pace = std::string(" --slow ") + c.slow + " --pause " + c.pause;
    const std::string base = c.scene + " --set T=" + exact_text(c.T) + " --fps " + exact_text(c.fps) + " --speed " +
                             exact_text(c.speed) + pace + " -q";
    SECTION(base) {
      ScratchDirectory dir;
      REQUIRE(run_vibra("render " + base + " -o " + (dir / "f_%04d.png")).exit_code == 0);
      const auto clock = vibra::scenes::FrameClock::paced(c.T, c.fps, c.speed, pacing(c.slow, c.pause));
      CHECK(count_files(dir.path, "f_") == clock.frames());
      const double steady = std::floor(c.T / c.speed * c.fps * (1 + 1e-12)) + 1;
      CHECK(clock.frames() == std::llround(steady + pacing(c.slow, c.pause).added_seconds(c.speed) * c.fps));
      for (long long k : c.ks) {
        const double t = clock.time(k);
        REQUIRE(run_vibra("render " + base + " --at " + exact_text(t) + " -o " + (dir / "still.png")).exit_code == 0);
        const double db = psnr(frame_name(dir, k), dir / "still.png");
        INFO("frame " << k << " at t = " << t << ": " << db << " dB");
        CHECK(db >= 45);
      }
      long long repeated = 0;
      for (long long k = 1; k < clock.frames(); ++k)
        if (clock.repeats(k)) {
          ++repeated;
          CHECK(read_file(frame_name(dir, k)) == read_file(frame_name(dir, k - 1)));
        }
      CHECK(repeated >= std::llround(pacing(nullptr, c.pause).added_seconds(1) * c.fps) - 1);
    }
  }
}

TEST_CASE("a paced video lasts its frames: the steady length plus the slowed and paused seconds", "[pacing][video]") {
  ScratchDirectory dir;
  // T = 4 at speed 1, 10 fps: 41 frames; 1-2 four times slower adds 3 s, the pause 1 s: 81 frames, 8.1 s.
  const auto r = run_vibra("render spring --size 320x180 --set dt=0.05 --set T=4 --fps 10 --speed 1 --slow 1-2:4 "
                           "--pause 3:1 -q -o " + (dir / "v.mp4"));
  REQUIRE(r.exit_code == 0);
  const std::string probe = shell("ffprobe -v error -count_frames -select_streams v:0 -show_entries "
                                  "stream=nb_read_frames:format=duration -of default=nw=1 '" + (dir / "v.mp4") + "'");
  CHECK_THAT(probe, Catch::Contains("nb_read_frames=81"));
  CHECK_THAT(probe, Catch::Contains("duration=8.1"));
}

TEST_CASE("a scene file's slow and pause lists pace the render as the flags do", "[pacing]") {
  ScratchDirectory dir;
  std::FILE* f = std::fopen((dir / "paced.toml").c_str(), "w");
  std::fputs("model = \"undamped\"\nlayout = \"plot\"\nT = 4\ndt = 0.05\nspeed = 1\nfps = 10\nsize = \"320x180\"\n"
             "slow = [{ from = 1, to = 2, factor = 4 }]\npause = [\"3:1\", { at = 0.5, seconds = 0.5 }]\n", f);
  std::fclose(f);
  REQUIRE(run_vibra("render " + (dir / "paced.toml") + " -q -o " + (dir / "f_%04d.png")).exit_code == 0);
  CHECK(count_files(dir.path, "f_") == 41 + 30 + 10 + 5);
  check_refused("render spring --slow 2-4:4 --slow 3-5:2 -o OUT.mp4", "overlaps 2-4:4");
  check_refused("render spring --slow 2-4:0 -o OUT.mp4", "above 0");
  check_refused("render spring --slow 4-2:3 -o OUT.mp4", "run forward");
  check_refused("render spring --pause 3 -o OUT.mp4", "is not T:SECONDS");
  check_refused("render spring --set T=4 --pause 5:1 -o OUT.mp4", "past the run's end");
  check_refused("render spring --set T=4 --slow 3-5:2 -o OUT.mp4", "reaches past the run's end");
  check_refused("render spring --set T=4 --pause 5:1 --at 1 -o OUT.png", "past the run's end");
}

TEST_CASE("the page maps the video's time through the render's pieces (page.js run by node)", "[pacing][page]") {
  if (shell("command -v node").empty()) {
    const char* why = "node is not installed: install the Debian package nodejs (scripts/setup does)";
    if (vibra::test::in_ci()) FAIL(why);
    WARN(why);
    return;
  }
  ScratchDirectory dir;
  REQUIRE(run_vibra("render spring --size 320x180 --set dt=0.05 --set T=4 --fps 10 --speed 1 --slow 1-2:4 "
                    "--pause 3:1 -q -o " + (dir / "page.html")).exit_code == 0);
  const std::string html = read_file(dir / "page.html");
  std::smatch map;
  REQUIRE(std::regex_search(html, map, std::regex("\"map\":(\\[\\[[^\"]*?\\]\\])")));
  const std::string js = read_file(std::string(VIBRA_SOURCE_DIR) + "/render/page/page.js");
  const auto begin = js.find("  const map = clock && clock.map;");
  const auto end = js.find("  const simulatedTime");
  REQUIRE(begin != std::string::npos);
  REQUIRE(end != std::string::npos);
  // The page's own functions, with its clock: every frame's simulated time, and the frame each time seeks to.
  const std::string script = "const clock = {fps: 10, frames: 81, map: " + map[1].str() +
                             "}; const lastFrame = 80;\n" + js.substr(begin, end - begin) +
                             "const out = []; for (let k = 0; k <= lastFrame; k++) out.push(mapped(k / clock.fps));\n"
                             "console.log(JSON.stringify(out)); console.log(JSON.stringify([mappedFrame(1.5), "
                             "mappedFrame(3), mappedFrame(3.5)]));\n";
  std::FILE* f = std::fopen((dir / "map.js").c_str(), "w");
  std::fputs(script.c_str(), f);
  std::fclose(f);
  const std::string out = shell("node '" + (dir / "map.js") + "'");
  const auto clock = vibra::scenes::FrameClock::paced(4, 10, 1, pacing("1-2:4", "3:1"));
  const std::string first_line = out.substr(0, out.find('\n'));
  // The same doubles: node prints the shortest form that reads back, %.17g may print more digits.
  std::vector<double> page_times;
  const std::regex number("[-0-9.e]+");
  for (std::sregex_iterator it(first_line.begin(), first_line.end(), number), e; it != e; ++it)
    page_times.push_back(std::stod(it->str()));
  REQUIRE(page_times.size() == std::size_t(clock.frames()));
  for (long long k = 0; k < clock.frames(); ++k) CHECK(page_times[k] == clock.time(k));
  // t = 1.5 is halfway through the slowed range (1 s + 2 s of video), t = 3 the pause's first frame (6 s), t = 3.5
  // half a second after the pause.
  CHECK_THAT(out, Catch::Contains("[30,60,75]"));
}

namespace {
/// Seconds from a WebVTT time, HH:MM:SS.mmm.
double vtt_seconds(const std::string& text) {
  return std::stoi(text.substr(0, 2)) * 3600 + std::stoi(text.substr(3, 2)) * 60 + std::stod(text.substr(6));
}

/// Each cue's start and end, in the order of the file.
std::vector<std::pair<double, double>> vtt_cue_times(const std::string& vtt) {
  std::vector<std::pair<double, double>> cues;
  const std::regex cue(R"((\d\d:\d\d:\d\d\.\d\d\d) --> (\d\d:\d\d:\d\d\.\d\d\d))");
  for (auto it = std::sregex_iterator(vtt.begin(), vtt.end(), cue); it != std::sregex_iterator(); ++it)
    cues.emplace_back(vtt_seconds((*it)[1]), vtt_seconds((*it)[2]));
  return cues;
}

/// The video time that first shows simulated time t, from the definition:
/// the integral of 1 / speed over [0, t] plus the pauses before t. Here
/// speed = rate outside 1-2 and rate / 2 inside it, and t = 3 is held 1 s.
double paced_video_time(double t, double rate) {
  const double slowed = std::clamp(t, 1.0, 2.0) - 1;  // the part of [0, t] inside 1-2
  return (t - slowed) / rate + 2 * slowed / rate + (t > 3 ? 1 : 0);
}
}  // namespace

TEST_CASE("a lecture's subtitles and chapters fall where the time map puts their times, to the millisecond",
          "[pacing][lecture][video]") {
  // A card of 1.2 s (12 frames), then T = 4 in 6.1 s: 61 frames, the last at
  // 6.0 s showing T; 2 - 1 = 1 time unit twice slower and 1 s held at t = 3,
  // so rate = (4 + 1) / (6 - 1) = 1, and frame k of the shot shows simulated
  // time 0.1 k, then 0.05 steps in 1-2, then 3 held, then 0.1 steps again.
  // The notes at 1.51-1.54 and 3.52-3.58 fall between frames, so they are
  // subtitles; 0.2-0.8 is drawn in the picture.
  ScratchDirectory dir;
  const std::string story = R"(size = "160x90"
fps = 10
[[shot]]
card = "Paced"
seconds = 1.2
[[shot]]
scene = "spring"
set = { T = 4, dt = 0.01 }
seconds = 6.1
slow = ["1-2:2"]
pause = [{ at = 3, seconds = 1 }]
notes = ["0.2-0.8: drawn", "1.51-1.54: slowed", "3.52-3.58: after the pause"]
)";
  std::FILE* f = std::fopen((dir / "story.toml").c_str(), "wb");
  REQUIRE(f);
  std::fputs(story.c_str(), f);
  std::fclose(f);
  const std::string out = dir / "paced.mp4";
  const auto r = run_vibra("lecture " + (dir / "story.toml") + " -q -o " + out);
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  const double card = 1.2, rate = (4 + 1) / (6.0 - 1), length = 6.1, shortest_cue = 2;
  const double slowed_start = card + paced_video_time(1.51, rate);
  const double after_start = card + paced_video_time(3.52, rate);
  const std::vector<std::pair<double, double>> expected = {
      {0, card},
      {slowed_start, std::min(slowed_start + shortest_cue, after_start)},
      {after_start, std::min(after_start + shortest_cue, card + length)}};
  const auto cues = vtt_cue_times(read_file(dir / "paced.vtt"));
  REQUIRE(cues.size() == expected.size());
  for (std::size_t i = 0; i < cues.size(); ++i) {
    INFO("cue " << i + 1);
    CHECK(cues[i].first == Approx(expected[i].first).margin(0.0005));
    CHECK(cues[i].second == Approx(expected[i].second).margin(0.0005));
  }
  // The chapters: the card, then the scene to the end of its 61 frames.
  const std::string chapters =
      shell("ffprobe -v error -show_entries chapter=start_time,end_time -of csv=p=0 '" + out + "'");
  double starts[2], ends[2];
  REQUIRE(std::sscanf(chapters.c_str(), "%lf,%lf\n%lf,%lf", &starts[0], &ends[0], &starts[1], &ends[1]) == 4);
  CHECK(starts[0] == Approx(0).margin(0.0005));
  CHECK(ends[0] == Approx(card).margin(0.0005));
  CHECK(starts[1] == Approx(card).margin(0.0005));
  CHECK(ends[1] == Approx(card + paced_video_time(4, rate) + 0.1).margin(0.0005));  // T's frame, then one frame long
}
