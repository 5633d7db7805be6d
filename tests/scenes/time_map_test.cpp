// Pacing: slow motion and pauses as a map from video time to simulated time.
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "core/error.hpp"
#include "scenes/timing/frame_clock.hpp"
#include "scenes/timing/pacing.hpp"
#include "scenes/timing/time_map.hpp"

using vibra::UsageError;
using vibra::scenes::FrameClock;
using vibra::scenes::Pacing;
using vibra::scenes::TimeMap;

namespace {
Pacing pacing(std::initializer_list<const char*> slow, std::initializer_list<const char*> pauses) {
  Pacing p;
  for (const char* s : slow) p.add_slow(s);
  for (const char* s : pauses) p.add_pause(s);
  return p;
}
}  // namespace

TEST_CASE("slow motion stretches its range by the factor, a pause holds its time", "[pacing]") {
  // T = 10 at 1 time unit per second; t = 2..4 four times slower; t = 6 held 1.5 s.
  const TimeMap map(10, 1, pacing({"2-4:4"}, {"6:1.5"}));
  CHECK(map.duration() == Approx(10 + 2 * 3 + 1.5));
  CHECK(map.simulated(1) == Approx(1));
  CHECK(map.simulated(2) == Approx(2));
  CHECK(map.simulated(6) == Approx(3));   // halfway through the slowed range: 4 s of video for 1 time unit
  CHECK(map.simulated(10) == Approx(4));  // its end
  CHECK(map.simulated(11) == Approx(5));
  CHECK(map.simulated(12) == 6);          // the pause: exactly t = 6 from 12 s ...
  CHECK(map.simulated(13.4) == 6);        // ... to 13.5 s
  CHECK(map.simulated(14.5) == Approx(7));
  CHECK(map.simulated(1e9) == 10);        // never past T
  CHECK(map.first_video_time(6) == Approx(12));
  CHECK(map.first_video_time(3) == Approx(6));
}

TEST_CASE("a factor below 1 plays faster: a pause at 0 or at T holds the first or last picture", "[pacing]") {
  const TimeMap fast(10, 1, pacing({"0-10:0.5"}, {}));
  CHECK(fast.duration() == Approx(5));
  CHECK(fast.simulated(2.5) == Approx(5));
  const TimeMap ends(4, 2, pacing({}, {"0:1", "4:2"}));
  CHECK(ends.duration() == Approx(1 + 2 + 2));
  CHECK(ends.simulated(0.5) == 0);
  CHECK(ends.simulated(2) == Approx(2));
  CHECK(ends.simulated(4) == 4);
}

TEST_CASE("the paced clock: frames at k / fps through the map, the video longer by what the pacing adds", "[pacing]") {
  const Pacing p = pacing({"1-2:3"}, {"3:1"});
  const FrameClock clock = FrameClock::paced(4, 10, 1, p);
  // 4 s steady + 1 time unit 3x slower (+2 s) + 1 s paused = 7 s: frames 0..70.
  CHECK(clock.frames() == 71);
  CHECK(p.added_seconds(1) == Approx(3));
  CHECK(clock.time(10) == Approx(1));
  CHECK(clock.time(25) == Approx(1.5));
  CHECK(clock.time(40) == Approx(2));
  CHECK(clock.time(50) == Approx(3));
  for (long long k = 51; k <= 60; ++k) {  // the pause: the same time, frames that repeat
    CHECK(clock.time(k) == 3);
    CHECK(clock.repeats(k));
  }
  CHECK_FALSE(clock.repeats(61));
  CHECK(clock.time(70) == Approx(4));
  // Without pacing, exactly the steady clock (its frame times bit for bit).
  const FrameClock steady = FrameClock::paced(4, 10, 1, Pacing{});
  CHECK_FALSE(steady.time_map());
  CHECK(steady.time(7) == 7 * (1.0 / 10));
}

TEST_CASE("seconds of video give the steady rate that makes the run last them", "[pacing]") {
  const Pacing p = pacing({"2-4:4"}, {"3:1"});
  const double rate = p.rate_for_length(10, 9);
  CHECK(TimeMap(10, rate, p).duration() == Approx(9));
  CHECK_THROWS_WITH(p.rate_for_length(10, 1), Catch::Contains("pauses alone take 1 s"));
}

TEST_CASE("ill-formed pacing is refused with one line naming the fix", "[pacing]") {
  Pacing p;
  CHECK_THROWS_WITH(p.add_slow("2-4"), Catch::Contains("is not T0-T1:FACTOR"));
  CHECK_THROWS_WITH(p.add_slow("4-2:3"), Catch::Contains("run forward"));
  CHECK_THROWS_WITH(p.add_slow("2-4:0"), Catch::Contains("above 0"));
  CHECK_THROWS_WITH(p.add_slow("2-4:-1"), Catch::Contains("above 0"));
  CHECK_THROWS_WITH(p.add_slow("2-4:nan"), Catch::Contains("is not T0-T1:FACTOR"));
  p.add_slow("2-4:4");
  CHECK_THROWS_WITH(p.add_slow("3-5:2"), Catch::Contains("overlaps 2-4:4"));
  CHECK_NOTHROW(p.add_slow("4-5:2"));  // touching is not overlapping
  CHECK_THROWS_WITH(p.add_pause("3"), Catch::Contains("is not T:SECONDS"));
  CHECK_THROWS_WITH(p.add_pause("-1:2"), Catch::Contains("0 or later"));
  CHECK_THROWS_WITH(p.add_pause("3:0"), Catch::Contains("above 0"));
  p.add_pause("3:1");
  CHECK_THROWS_WITH(p.add_pause("3:2"), Catch::Contains("already paused"));
  CHECK_THROWS_WITH(TimeMap(4.5, 1, p), Catch::Contains("reaches past the run's end"));
  Pacing late;
  late.add_pause("12:1");
  CHECK_THROWS_WITH(TimeMap(10, 1, late), Catch::Contains("past the run's end T = 10"));
  for (const char* text : {"2-4", "x-y:z", ":", "", "2-4:4:4"}) {
    Pacing q;
    CHECK_THROWS_AS(q.add_slow(text), UsageError);
  }
}

namespace {
constexpr int kPoints = 400, kCellsPerPoint = 60;

/// Video times of simulated times t_i = T i / kPoints from the definition:
/// the integral of 1 / speed(s) over [0, t_i], speed = rate / factor(s),
/// plus every pause at a time before t_i (a pause at t_i itself starts when
/// t_i is first shown). The integral by the midpoint rule on cells whose
/// edges fall on every range's ends (the cases' ends are multiples of T/24000),
/// where 1 / speed is constant: a sum of the definition, not the map's pieces.
std::vector<double> video_times_by_integral(const Pacing& p, double rate, double T) {
  const double h = T / (kPoints * kCellsPerPoint);
  std::vector<double> times = {0};
  double integral = 0;
  for (int cell = 0; cell < kPoints * kCellsPerPoint; ++cell) {
    const double s = (cell + 0.5) * h;
    double factor = 1;
    for (const auto& range : p.slow)
      if (s >= range.from && s < range.to) factor = range.factor;
    integral += h * factor / rate;
    if ((cell + 1) % kCellsPerPoint) continue;
    const double t = T * ((cell + 1) / kCellsPerPoint) / kPoints;
    double held = 0;
    for (const auto& pause : p.pauses) held += pause.at < t ? pause.seconds : 0;
    times.push_back(integral + held);
  }
  return times;
}
}  // namespace

TEST_CASE("every simulated time's video time is the pacing integral plus the pauses before it", "[pacing]") {
  struct Case {
    double T, rate;
    std::vector<const char*> slow, pauses;
  };
  const Case cases[] = {
      {10, 1, {"2-4:4"}, {"6:1.5"}},
      {10, 0.7, {"1-3:2", "5-6:0.25"}, {"0:1", "3:0.5", "8:2"}},
      {4, 2, {"0-4:3"}, {"4:1"}},              // slow from start to end, a pause at T
      {6, 1.3, {"2-3:5"}, {"2:1", "3:0.25"}},  // pauses at a range's start and end
  };
  for (const Case& c : cases) {
    Pacing p;
    for (const char* text : c.slow) p.add_slow(text);
    for (const char* text : c.pauses) p.add_pause(text);
    const TimeMap map(c.T, c.rate, p);
    INFO("T = " << c.T << ", rate = " << c.rate << ", " << p.describe());
    const std::vector<double> expected = video_times_by_integral(p, c.rate, c.T);
    for (int i = 0; i <= kPoints; ++i) {
      const double t = c.T * i / kPoints;
      INFO("t = " << t);
      CHECK(map.first_video_time(t) == Approx(expected[i]).margin(1e-9));
      // And back: the map shows t at that video time (the first of a pause's).
      CHECK(map.simulated(expected[i]) == Approx(t).margin(1e-9));
    }
    const double held_at_end = p.pauses.back().at == c.T ? p.pauses.back().seconds : 0;
    CHECK(map.duration() == Approx(expected.back() + held_at_end).margin(1e-9));
  }
}

TEST_CASE("adjacent slow-motion ranges: the second's factor from where the first ends, a pause between them", "[pacing]") {
  // T = 6 at 1 unit per second: t = 1-3 twice slower (4 s), 1 s held at t = 3,
  // t = 3-5 four times slower (8 s): 1 + 4 + 1 + 8 + 1 = 15 s.
  const TimeMap map(6, 1, pacing({"1-3:2", "3-5:4"}, {"3:1"}));
  CHECK(map.duration() == Approx(15));
  CHECK(map.first_video_time(2) == Approx(3));
  CHECK(map.first_video_time(3) == Approx(5));  // the pause's start
  CHECK(map.simulated(5.5) == 3);
  CHECK(map.first_video_time(4) == Approx(1 + 4 + 1 + 4));
  CHECK(map.simulated(12) == Approx(3 + (12 - 6) / 4.0));
  CHECK(map.first_video_time(5.5) == Approx(14.5));
}
