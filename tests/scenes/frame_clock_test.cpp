// Tests of the frame clock: frames at t_k = k speed / fps, and frame counts that overflow refused.
#include <catch2/catch.hpp>

#include "core/error.hpp"
#include "scenes/timing/frame_clock.hpp"

using vibra::scenes::FrameClock;

TEST_CASE("frames at t_k = k speed / fps while t_k <= T", "[frames]") {
  auto c = FrameClock::by_speed(2 * M_PI * 6, 30, M_PI);  // 6 periods, one period in 2 s: 12 s of video
  CHECK(c.frames() == 361);
  CHECK(c.time(0) == 0);
  CHECK(c.time(360) == Approx(12 * M_PI));
  auto exact = FrameClock::by_speed(1, 10, 1);  // t_k = 0, 0.1, ..., 1.0: the end is a frame
  CHECK(exact.frames() == 11);
  auto short_run = FrameClock::by_speed(0.05, 10, 1);
  CHECK(short_run.frames() == 1);
}

TEST_CASE("one frame per step", "[frames]") {
  auto c = FrameClock::per_step(2 * M_PI / 40, 480);
  CHECK(c.frames() == 481);
  CHECK(c.time(40) == Approx(2 * M_PI));
}

TEST_CASE("a frame count that overflows or exceeds the bound is refused, not wrapped", "[frames]") {
  using vibra::UsageError;
  // T / (speed / fps) = 10 * 30 / 1e-300 = 3e302: far beyond any integer.
  CHECK_THROWS_AS(FrameClock::by_speed(10, 30, 1e-300), UsageError);
  CHECK_THROWS_WITH(FrameClock::by_speed(10, 30, 1e-300), Catch::Contains("frames"));
  CHECK_THROWS_AS(FrameClock::by_speed(10, 30, 0), UsageError);     // an infinite count
  CHECK_THROWS_AS(FrameClock::by_speed(10, 30, NAN), UsageError);   // not a number
  CHECK_THROWS_AS(FrameClock::by_speed(1e9, 30, 1), UsageError);    // 3e10 frames: over the bound
  CHECK_THROWS_AS(FrameClock::per_step(1e-9, 2'000'000'000LL), UsageError);
  CHECK(FrameClock::by_speed(1e6, 30, 1).frames() == 30'000'001);  // a big but sane count passes
}

TEST_CASE("the frame showing a time, and the frame a pause's repeats show", "[frames]") {
  auto c = FrameClock::by_speed(1, 10, 1);  // t_k = k / 10
  CHECK(c.first_frame_from(0) == 0);
  CHECK(c.first_frame_from(0.3) == 3);   // a frame's own time
  CHECK(c.first_frame_from(0.31) == 4);  // between frames: the next
  CHECK(c.first_frame_from(1.5) == 11);  // after the last frame: none
  CHECK(c.drawn_frame(7) == 7);          // no pauses: every frame is drawn
  vibra::scenes::Pacing pacing;
  pacing.add_pause("0.5:0.3");  // frames 5..8 all show t = 0.5
  auto paused = FrameClock::paced(1, 10, 1, pacing);
  REQUIRE(paused.time(5) == Approx(0.5));
  REQUIRE(paused.repeats(8));
  REQUIRE_FALSE(paused.repeats(9));
  CHECK(paused.first_frame_from(paused.time(5)) == 5);
  CHECK(paused.drawn_frame(8) == 5);
  CHECK(paused.drawn_frame(5) == 5);
  CHECK(paused.drawn_frame(9) == 9);
}
