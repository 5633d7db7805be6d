// The stop flag's progress line: the time left in the unit a person reads, at each unit's edges.
#include <catch2/catch.hpp>

#include "core/stop_flag.hpp"

using vibra::time_left_text;

TEST_CASE("a long run's time left is written in seconds, minutes, hours, days or years", "[stop]") {
  constexpr double kDay = 86400, kYear = 365.25 * kDay;
  const struct {
    double seconds;
    const char* text;
  } cases[] = {
      {0, "0 s"},
      {40.4, "40 s"},
      {119.4, "119 s"},
      {120, "2 min"},         // from two minutes on, minutes
      {7199, "120 min"},
      {7200, "2.0 h"},        // from two hours on, hours to a tenth
      {5.25 * 3600, "5.2 h"}, // printf rounds the binary value: 5.25 h is exact, and goes to even
      {2 * kDay - 1, "48.0 h"},
      {2 * kDay, "2 days"},   // from two days on, whole days
      {2.5 * kDay - 1, "2 days"},
      {2.5 * kDay + 1, "3 days"},
      {kYear - 1, "365 days"},
      {kYear, "1 year"},      // from a year on, years to two digits
      {1.04 * kYear, "1 year"},
      {1.06 * kYear, "1.1 years"},
      {270 * kYear, "2.7e+02 years"},
  };
  for (const auto& c : cases) {
    INFO(c.seconds << " s");
    CHECK(time_left_text(c.seconds) == c.text);
  }
}
