// orbit --long's verdict on made-up blocks: when a phase drift is linear enough to extrapolate, and the energy's trend.
#include <catch2/catch.hpp>
#include <cmath>
#include <functional>
#include <string>

#include "core/analysis/long_run_verdict.hpp"

using namespace vibra;
using Catch::Matchers::Contains;

namespace {
/// A run of 100 blocks of 1000 orbits, phase(orbits) and energy_error(orbits) at each block's end.
OrbitRun made_up_run(const std::function<double(long long)>& phase, const std::function<double(long long)>& energy) {
  OrbitRun run{200, 2 * M_PI / 200, 0.5, 1.0, {}};
  for (long long orbits = 1000; orbits <= 100'000; orbits += 1000)
    run.blocks.push_back({orbits, 0.1, phase(orbits), energy(orbits)});
  return run;
}
double flat(long long) { return 1e-9; }
}  // namespace

TEST_CASE("orbit --long: a steady drift is fitted and extrapolated to 1e9 orbits", "[analysis][orbit]") {
  // -1e-3 rad an orbit with a small wobble: the drift over the run is 100 rad, the wobble 0.05.
  const LongRunVerdict v = judge_long_run(made_up_run([](long long n) { return -1e-3 * n + 0.05 * std::sin(n / 7e3); }, flat));
  CHECK(v.linear);
  CHECK(v.fit.slope == Approx(-1e-3).epsilon(1e-3));
  CHECK(v.residual > 0.04);  // the wobble, and the line's small tilt towards it
  CHECK(v.residual < 0.1);
  CHECK(v.fit(kExtrapolatedOrbits) == Approx(-1e6).epsilon(1e-3));
  CHECK(v.max_energy_error == 1e-9);
  CHECK_THAT(v.text, Contains("200 steps/orbit: the phase drifts linearly, -0.001 rad per orbit"));
  CHECK_THAT(v.text, Contains("the energy error stays bounded (at most 1e-09)"));
  CHECK_THAT(v.text, Contains("(more than half an orbit"));
  // Kepler: 3 dE of frequency, over 2 pi 1e9 of time: 3e-9 * 2 pi * 1e9 = 18.8 rad.
  CHECK_THAT(v.text, Contains("could add up to 19 rad"));
}

TEST_CASE("orbit --long: a phase error that wanders has no trend to extrapolate", "[analysis][orbit]") {
  const LongRunVerdict v = judge_long_run(made_up_run([](long long n) { return 0.3 * std::sin(n / 1e4); }, flat));
  CHECK_FALSE(v.linear);
  CHECK_THAT(v.text, Contains("does not drift steadily"));
  CHECK_THAT(v.text, Contains("no trend to extrapolate"));
  CHECK_THAT(v.text, Contains("the position error stays below 0.5"));
}

TEST_CASE("orbit --long: linear means the line misses by at most a tenth of the drift", "[analysis][orbit]") {
  // A drift of 1e-4 an orbit (10 rad over the run) with blocks alternately above and below it.
  const auto wobbled = [](double amplitude) {
    return [amplitude](long long n) { return 1e-4 * n + (n / 1000 % 2 ? amplitude : -amplitude); };
  };
  const LongRunVerdict inside = judge_long_run(made_up_run(wobbled(0.95), flat));
  const LongRunVerdict outside = judge_long_run(made_up_run(wobbled(1.05), flat));
  CHECK(inside.residual < 0.1 * std::abs(inside.fit.slope) * 1e5);
  CHECK(inside.linear);
  CHECK(outside.residual > 0.1 * std::abs(outside.fit.slope) * 1e5);
  CHECK_FALSE(outside.linear);
}

TEST_CASE("orbit --long: the energy error grows when its second half's largest is over twice the first's", "[analysis][orbit]") {
  const auto steady = [](long long n) { return 1e-5 * n; };
  const auto halves = [](double first, double second) {
    return [first, second](long long n) { return n <= 50'000 ? first : second; };
  };
  const LongRunVerdict doubled = judge_long_run(made_up_run(steady, halves(1e-8, 2e-8)));
  CHECK_THAT(doubled.text, Contains("stays bounded (at most 2e-08)"));
  const LongRunVerdict grown = judge_long_run(made_up_run(steady, halves(1e-8, 2.1e-8)));
  CHECK_THAT(grown.text, Contains("grows (at most 2.1e-08)"));
  CHECK_THAT(grown.text, Contains("(the growing energy error says it may not)"));
  CHECK(grown.max_energy_error == 2.1e-8);
  // The block ending at the middle, 50000 orbits, is the first half's.
  const LongRunVerdict middle =
      judge_long_run(made_up_run(steady, [](long long n) { return n == 50'000 ? 5e-8 : 1e-8; }));
  CHECK_THAT(middle.text, Contains("stays bounded (at most 5e-08)"));
  // Below 1e-11 the energy error is rounding, even ten times larger in the second half.
  const LongRunVerdict rounding = judge_long_run(made_up_run(steady, halves(1e-13, 1e-12)));
  CHECK_THAT(rounding.text, Contains("stays at the level of rounding"));
  CHECK_THAT(rounding.text, !Contains("may not"));
}

TEST_CASE("orbit --long: the position error of a phase error is the chord, at most the diameter", "[analysis][orbit]") {
  CHECK(chord(0) == 0);
  CHECK(chord(M_PI / 3) == Approx(1));
  CHECK(chord(-M_PI / 3) == Approx(1));
  CHECK(chord(M_PI) == Approx(2));
  CHECK(chord(2 * M_PI) == Approx(0).margin(1e-12));
  CHECK(chord(1e-6) == Approx(1e-6));
  for (double phase = -20; phase <= 20; phase += 0.01) CHECK(chord(phase) <= 2);
}
