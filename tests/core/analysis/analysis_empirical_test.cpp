// Empirical periods and amplitudes from the extrema (docs/analysis.md).
#include <catch2/catch.hpp>
#include <cmath>

#include "core/analysis/empirical.hpp"
#include "core/analysis/frequency/numerical_frequency.hpp"
#include "test_support.hpp"

using namespace vibra;

TEST_CASE("empirical periods of the centered scheme are 2 pi / w~ of (1.18)", "[analysis]") {
  const double w = 2 * M_PI;
  for (double dt : {0.1, 0.05, 0.03, 0.0123}) {
    INFO("dt=" << dt);
    auto t = test::trajectory("undamped", {"dt=" + test::str(dt), "T=20"});
    const auto cycles = oscillation_cycles(*t);
    REQUIRE(cycles.size() >= 18);
    const double expected = 2 * M_PI / numerical_frequency(w, dt);
    for (const auto& c : cycles) {
      CHECK(c.period == Approx(expected).epsilon(1e-6));
      CHECK(c.amplitude == Approx(1).epsilon(1e-9));  // u^n = cos(w~ t_n) keeps I = 1
    }
    CHECK(cycles[3].t == Approx(4 * expected).epsilon(1e-6));
  }
}

TEST_CASE("extrema at mesh points give periods that are multiples of dt, as the book's code", "[analysis]") {
  const double dt = 0.1;
  auto t = test::trajectory("undamped", {"dt=0.1", "T=10"});
  const auto cycles = oscillation_cycles(*t, ExtremumTiming::mesh);
  REQUIRE(cycles.size() >= 8);
  bool jumps = false;
  for (const auto& c : cycles) {
    CHECK(std::abs(c.period / dt - std::round(c.period / dt)) < 1e-9);
    jumps |= std::abs(c.period - cycles[0].period) > dt / 2;
  }
  CHECK(jumps);  // 2 pi / w~ = 0.983 is no multiple of 0.1: the periods jump between 0.9 and 1.0
}

TEST_CASE("empirical amplitudes follow the damping and Forward Euler's growth", "[analysis]") {
  // u'' + b u' + 4 u = 0: the amplitude falls by exp(-b p / 2) per period.
  const double b = 0.1;
  auto damped = test::trajectory("vibration", {"b=0.1", "s=4*u", "dt=0.001", "T=30"});
  const auto cycles = oscillation_cycles(*damped);
  REQUIRE(cycles.size() >= 5);
  for (size_t i = 1; i < cycles.size(); ++i)
    CHECK(cycles[i].amplitude / cycles[i - 1].amplitude == Approx(std::exp(-b * cycles[i - 1].period / 2)).epsilon(2e-3));

  // Forward Euler multiplies the amplitude by sqrt(1 + w^2 dt^2) per step.
  const double dt = 0.01, w = 2 * M_PI;
  auto growing = test::trajectory("undamped", {"scheme=forward-euler", "dt=0.01", "T=5"});
  const auto grown = oscillation_cycles(*growing);
  REQUIRE(grown.size() >= 3);
  const double per_period = std::pow(1 + w * w * dt * dt, grown[1].period / dt / 2);
  CHECK(grown[2].amplitude / grown[1].amplitude == Approx(per_period).epsilon(2e-3));
}

TEST_CASE("a stream of samples yields one cycle per completed period", "[analysis]") {
  EmpiricalOscillation oscillation;
  int cycles = 0;
  for (int n = 0; n <= 1000; ++n)
    if (auto c = oscillation.add(n * 0.01, std::sin(2 * M_PI * n * 0.01))) {
      CHECK(c->i == cycles++);
      CHECK(c->period == Approx(1).epsilon(1e-9));
    }
  // Maxima at t = 0.25, 1.25, ..., 9.25: nine periods between ten maxima.
  CHECK(cycles == 9);
}

TEST_CASE("an extremum no sinusoid about zero fits is the parabola's through its three samples, time and value",
          "[analysis]") {
  // Samples every 0.25 of a period-2 signal: maxima 10 at t = 0, 2, 4 (equal
  // neighbours: the sinusoid's fit is the sample itself), minima on the
  // parabola 3 + (t - 1.1)^2 around t = 1.1, between mesh points. There
  // (u^{n-1} + u^{n+1}) / (2 u^n) > 1, so no sinusoid about zero fits and the
  // parabola through the three samples, exact for them, places the minimum:
  // at t = 1.1 with u = 3, so the amplitude is (10 - 3) / 2.
  const double period[] = {10, 9, 6, 3.1225, 3.01, 3.0225, 6, 9};
  EmpiricalOscillation oscillation(ExtremumTiming::fitted);
  std::vector<OscillationCycle> cycles;
  for (int k = 0; k <= 8 * 4; ++k)
    if (auto cycle = oscillation.add(0.25 * k, period[k % 8])) cycles.push_back(*cycle);
  REQUIRE(cycles.size() == 2);
  for (const OscillationCycle& c : cycles) {
    INFO("cycle " << c.i);
    CHECK(c.t == Approx(2.0 * (c.i + 1)));
    CHECK(c.period == Approx(2.0).epsilon(1e-12));
    CHECK(c.amplitude == Approx(3.5).epsilon(1e-12));
  }
}
