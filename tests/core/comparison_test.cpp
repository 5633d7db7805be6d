// Comparisons: --compare KEY=V1,V2,... parsed, members built and advanced in
// lock step, a member that blows up stopped while the others go on.
#include <catch2/catch.hpp>

#include <cmath>

#include "core/comparison.hpp"
#include "core/error.hpp"
#include "test_support.hpp"

using namespace vibra;

namespace {
void check_error(const std::function<void()>& action, const std::string& expected) {
  try {
    action();
    FAIL("no error; expected: " << expected);
  } catch (const UsageError& e) {
    CHECK_THAT(e.what(), Catch::Contains(expected));
  }
}
}  // namespace

TEST_CASE("a comparison KEY=V1,V2 parses to a key and its values", "[comparison]") {
  const ComparisonRequest r = parse_comparison(" dt = 0.1, 2*pi/40 ,0.05");
  CHECK(r.key == "dt");
  CHECK(r.values == std::vector<std::string>{"0.1", "2*pi/40", "0.05"});
  check_error([] { parse_comparison("scheme"); }, "not KEY=V1,V2");
  check_error([] { parse_comparison("=rk4"); }, "not KEY=V1,V2");
  check_error([] { parse_comparison("dt="); }, "empty value");
  check_error([] { parse_comparison("dt=0.1,,0.2"); }, "empty value");
  check_error([] { parse_comparison("scheme=rk4,rk2,rk4"); }, "scheme=rk4 is given twice");
  check_error([] { parse_comparison("dt=1,2,3,4,5,6,7,8,9"); }, "at most 8");
  CHECK(parse_comparison("dt=1,2,3,4,5,6,7,8").values.size() == 8);
}

TEST_CASE("members are the base settings with each value of the key", "[comparison]") {
  const Parameters base = model_settings("pendulum", {"alpha=0", "periods=2"});
  const auto members = comparison_members(base, parse_comparison("Theta=10,120"));
  REQUIRE(members.size() == 2);
  CHECK(members[1].angle("Theta") == Approx(120 * M_PI / 180));
  CHECK(members[1].number("alpha") == 0);
  check_error([&] { comparison_members(base, parse_comparison("alpha=0.1,0.2")); }, "alpha is given both in --set and in --compare");
  check_error([&] { comparison_members(base, parse_comparison("Thta=10,20")); }, "did you mean 'Theta'");
  check_error([&] { comparison_members(base, parse_comparison("scheme=rk4,rk5")); }, "'rk5' is not a valid scheme");
}

TEST_CASE("members advance in lock step, each with its own dt", "[comparison]") {
  Comparison c(find_model("undamped"), model_settings("undamped", {"scheme=rk4", "T=1"}), parse_comparison("dt=0.1,0.025,0.03"));
  REQUIRE(c.size() == 3);
  CHECK(c.label(1) == "dt = 0.025");
  std::vector<int> samples(3);
  c.advance_to(0.5, [&](size_t m, std::span<const double> row) {
    ++samples[m];
    CHECK(row[0] <= 0.5 + c.trajectory(m).info().mesh.dt);
  });
  // t = 0 and every step up to the first at or after 0.5, and no further.
  for (size_t m = 0; m < 3; ++m) {
    const double dt = c.trajectory(m).info().mesh.dt;
    CHECK(samples[m] == c.trajectory(m).index() + 1);
    CHECK(c.trajectory(m).t() >= 0.5 - 1e-12);
    CHECK(c.trajectory(m).t() < 0.5 + dt - 1e-12);
  }
  std::vector<double> row(3);
  for (size_t m = 0; m < 3; ++m) {
    c.row_at(m, 0.5, row);
    CHECK(row[0] == 0.5);
    // RK4 errs by 2e-3 at dt = 0.1; at dt = 0.03, 0.5 lies between steps, on a chord (w dt)^2/8 = 4e-3 off the peak.
    CHECK(row[1] == Approx(std::cos(M_PI)).margin(7e-3));
    // Exactly the member's own run, read between its samples on the straight
    // line through them (a fixed-step scheme computes nothing between).
    const double dt = c.trajectory(m).info().mesh.dt;
    const auto own = vibra::test::rows(*vibra::test::trajectory("undamped", {"scheme=rk4", "T=1", "dt=" + vibra::test::str(dt)}));
    size_t k = 0;
    while (own[k + 1][0] < 0.5) ++k;
    const double s = (0.5 - own[k][0]) / (own[k + 1][0] - own[k][0]);
    INFO("member dt = " << dt << ", between t = " << own[k][0] << " and " << own[k + 1][0]);
    CHECK(row[1] == Approx(own[k][1] + s * (own[k + 1][1] - own[k][1])).margin(1e-12));
    CHECK(row[2] == Approx(own[k][2] + s * (own[k + 1][2] - own[k][2])).margin(1e-11));
  }
  c.advance_to(10);  // past the end: every member stops at T
  for (size_t m = 0; m < 3; ++m) CHECK(c.trajectory(m).done());
  CHECK(c.end_time() == Approx(1));
}

TEST_CASE("a member that blows up stops and the others go on", "[comparison]") {
  Comparison c(find_model("undamped"), model_settings("undamped", {"steps_per_period=20", "periods=6"}),
               parse_comparison("scheme=forward-euler,crank-nicolson,rk4"));
  c.set_escape_limit(2);
  double last_fe = 0;
  c.advance_to(c.end_time(), [&](size_t m, std::span<const double> row) {
    if (m == 0) last_fe = row[0];
  });
  // Forward Euler's amplitude grows by sqrt(1 + w^2 dt^2) per step: it passes
  // twice I after ln 4 / ln(1 + (2 pi/20)^2) = 14.7 steps, and u follows at its
  // next extremum, by t = 1 (amplitude 2.56 there).
  const double steps = std::log(4) / std::log(1 + std::pow(2 * M_PI / 20, 2));
  REQUIRE(c.blew_up(0));
  CHECK(c.blow_up_time(0) >= steps * 0.05);
  CHECK(c.blow_up_time(0) <= 1.05);
  CHECK(last_fe == c.blow_up_time(0));
  CHECK_FALSE(c.blew_up(1));
  CHECK_FALSE(c.blew_up(2));
  CHECK(c.trajectory(2).done());
}

TEST_CASE("a member whose solution turns non-finite blows up there", "[comparison]") {
  // u'' = u^3 (s = -u^3) escapes to infinity in finite time.
  Comparison c(find_model("vibration"), model_settings("vibration", {"s=-u^3", "I=1", "V=1", "dt=0.01", "T=5"}),
               parse_comparison("scheme=forward-euler,rk4"));
  c.advance_to(5);
  CHECK(c.blew_up(0));
  CHECK(c.blew_up(1));
  CHECK(c.blow_up_time(1) < 2);
}
