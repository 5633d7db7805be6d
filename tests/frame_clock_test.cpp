#include <catch2/catch.hpp>

#include "scenes/frame_clock.hpp"

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
