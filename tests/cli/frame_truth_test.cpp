// Frame = still: frame k of a render is the picture `--at t_k` draws, for
// every built-in scene and a grid of frame rates, speeds (slow motion to
// 100x), time steps (fine to coarse), comparisons, layouts, panels, energy
// bars and moving windows. Frames and stills go through the real command;
// their pixels must be the same, bit for bit: a curve a frame's layer grew
// piece by piece is stroked as the whole curve is (docs/render.md).
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "cli_support.hpp"
#include "png_compare.hpp"

using vibra::test::exact_text;
using vibra::test::psnr;
using vibra::test::run_vibra;
using vibra::test::ScratchDirectory;
namespace fs = std::filesystem;

namespace {


struct Case {
  std::string args;           ///< scene and settings, without --fps/--speed/-o
  double fps, speed;          ///< speed 0: one frame per solver step of `step`
  std::vector<long long> ks;  ///< frames to compare (negative: from the end)
  double step = 0;            ///< the solver's dt, for one frame per step
};

/// Renders the frames, then a still at each chosen frame's time, and holds
/// each pair to be identical (infinite PSNR).
void check_frames_are_stills(const Case& c) {
  ScratchDirectory dir;
  const std::string timing = c.speed > 0 ? " --fps " + exact_text(c.fps) + " --speed " + exact_text(c.speed) : "";
  const std::string base = c.args + timing + " -q";
  INFO("vibra render " << base);
  const auto frames = run_vibra("render " + base + " -o " + (dir / "f_%05d.png"));
  REQUIRE(frames.exit_code == 0);
  long long count = 0;
  for (const auto& e : fs::directory_iterator(dir.path)) count += e.path().extension() == ".png";  // not the ledger
  REQUIRE(count >= 2);
  for (long long k : c.ks) {
    if (k < 0) k += count;
    REQUIRE(k < count);
    // The frame clock's own arithmetic: k times the frame interval.
    const double t = c.speed > 0 ? double(k) * (c.speed / c.fps) : double(k) * c.step;
    const auto still = run_vibra("render " + base + " --at " + exact_text(t) + " -o " + (dir / "still.png"));
    REQUIRE(still.exit_code == 0);
    char frame[32];
    std::snprintf(frame, sizeof frame, "f_%05lld.png", k);
    const double db = psnr(dir / frame, dir / "still.png");
    INFO("frame " << k << " at t = " << t << ": " << db << " dB");
    CHECK(std::isinf(db));
  }
}

}  // namespace

TEST_CASE("every built-in scene's frames are its stills, in slow motion and fast", "[heavy][frame-truth]") {
  for (const char* scene : {"pendulum", "spring", "spring_dashpot", "washing_machine", "sliding_box", "bumpy_road",
                            "bouncing_ball", "rlc", "elastic_pendulum", "orbit"}) {
    const std::string s = std::string(scene) + " --size 320x180";
    SECTION(std::string(scene) + ": 0.25x at 10 fps, frames far shorter than a step") {
      check_frames_are_stills({s + " --set T=3", 10, 0.25, {3, 17, -1}});
    }
    SECTION(std::string(scene) + ": 1x at 30 fps") { check_frames_are_stills({s + " --set T=6", 30, 1, {5, 61, -1}}); }
  }
}

TEST_CASE("frames are stills across time steps, speeds, layouts and comparisons", "[heavy][frame-truth]") {
  const std::vector<Case> cases = {
      {"spring --size 320x180 --set T=8 --set dt=0.1", 60, 1, {7, 50, -1}},        // coarse dt, high fps
      {"spring --size 320x180 --set T=8 --set dt=0.001", 10, 2, {3, 5, -1}},       // thousands of steps a frame
      {"spring --size 320x180 --set T=40", 10, 100, {1, 2, -1}},                   // 100x
      {"pendulum --size 320x180 --set T=2", 60, 0.1, {7, 601, -1}},                // 0.1x
      {"pendulum_book --size 320x180 --set periods=1", 0, 0, {3, 17, -1}, 2 * M_PI / 40},  // a frame per step
      {"spring --size 320x180 --set T=4 --compare dt=0.2,0.1,0.05", 10, 0.25, {3, 8, -1}},
      {"spring --size 640x360 --set T=4 --compare scheme=forward-euler,backward-euler,crank-nicolson,rk4 "
       "--panels u,phase",
       30, 1, {7, 50, -1}},
      {"pendulum --size 320x180 --set T=8 --window 2", 30, 1, {7, 50, -1}},
      {"pendulum --size 320x180 --set T=8 --window 2 --window-mode jumps", 30, 1, {7, 70, -1}},
      {"spring_dashpot --size 640x360 --set T=8 --energy-bars --panels u,phase,energy", 30, 1, {7, 50, -1}},
      {"spring --size 320x180 --set T=2 --layout plot", 60, 0.1, {7, 50, -1}},
      {"spring --size 320x180 --set T=2 --layout grid --compare dt=0.2,0.1", 60, 0.1, {7, 50, 850, -1}},
      // Adaptive schemes: uneven steps, frames from dopri5's dense output
      // (rkf45's Hermite), a loose tolerance so steps span several frames.
      {"spring --size 320x180 --set T=6 --set scheme=dopri5 --set rtol=1e-4", 30, 1, {5, 61, -1}},
      {"pendulum --size 320x180 --set T=8 --set scheme=rkf45 --window 2", 30, 1, {7, 50, -1}},
      {"spring --size 640x360 --set T=4 --compare scheme=centered,dopri5 --panels u,phase", 30, 1, {7, 50, -1}},
      {"bouncing_ball --size 320x180 --set T=3 --set scheme=dopri5", 10, 0.25, {3, 17, -1}},
      {"spring --size 320x180 --set T=2 --set dt=0.05 --set scheme=dopri5 --frame-per-step", 0, 0, {3, 17, -1}, 0.05},
  };
  for (const Case& c : cases)
    SECTION(c.args + " at " + exact_text(c.fps) + " fps, speed " + exact_text(c.speed)) { check_frames_are_stills(c); }
}
