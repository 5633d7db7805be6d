// The circular orbit of two-body (Exercise 1.28) and the line fitted to its phase drift.
#include <catch2/catch.hpp>
#include <cmath>
#include <ctime>
#include <vector>

#include "core/analysis/line_fit.hpp"
#include "core/analysis/orbit_error.hpp"
#include "test_support.hpp"

using namespace vibra;

TEST_CASE("the circular orbit's error falls with the schemes' order", "[analysis]") {
  struct Case {
    const char* scheme;
    int order, steps_per_orbit;  ///< RK4 reaches its asymptotic rate later than PEFRL
  };
  for (Case c : {Case{"pefrl", 4, 400}, {"rk4", 4, 1600}, {"euler-cromer", 1, 400}}) {
    INFO(c.scheme);
    const OrbitRun coarse = circular_orbit_run(c.scheme, c.steps_per_orbit, 10, 10);
    const OrbitRun fine = circular_orbit_run(c.scheme, 2 * c.steps_per_orbit, 10, 10);
    CHECK(coarse.dt == Approx(2 * M_PI / c.steps_per_orbit));
    CHECK(std::log2(coarse.max_error / fine.max_error) == Approx(c.order).margin(0.2));
  }
}

TEST_CASE("an orbit run records the largest error per block of orbits", "[analysis]") {
  long long last_progress = 0;
  const std::clock_t before = std::clock();
  const OrbitRun run = circular_orbit_run("pefrl", 100, 50, 10, [&](long long done) { last_progress = done; });
  const double spent = double(std::clock() - before) / CLOCKS_PER_SEC;
  REQUIRE(run.blocks.size() == 5);
  CHECK(run.blocks[0].orbits == 10);
  CHECK(run.blocks.back().orbits == 50);
  CHECK(last_progress == 50);
  double largest = 0;
  for (const auto& b : run.blocks) largest = std::max(largest, b.max_error);
  CHECK(run.max_error == largest);
  // A symplectic scheme's phase error grows linearly: 5 blocks on, 5 times the error.
  CHECK(run.blocks[4].max_error / run.blocks[0].max_error == Approx(5).epsilon(0.1));
  // The run's own CPU time: some, and no more than the call took.
  CHECK(run.cpu_seconds > 0);
  CHECK(run.cpu_seconds <= spent);
}

TEST_CASE("a long run's blocks follow the phase and the energy error", "[analysis]") {
  // PEFRL at 100 steps an orbit falls behind by the same angle every orbit
  // (its 4th-order phase error), while its energy error stays at rounding.
  const OrbitRun run = circular_orbit_run("pefrl", 100, 40, 4);
  REQUIRE(run.blocks.size() == 10);
  std::vector<double> orbits, phases;
  for (const auto& b : run.blocks) orbits.push_back(b.orbits), phases.push_back(b.phase);
  const Line fit = fit_line(orbits, phases);
  INFO("phase drift " << fit.slope << " rad per orbit");
  CHECK(fit.slope < -1e-7);
  CHECK(std::abs(fit.intercept) < 0.01 * std::abs(fit.slope) * 40);
  CHECK(largest_residual(fit, orbits, phases) < 0.01 * std::abs(fit.slope) * 40);
  CHECK(run.blocks.back().phase / run.blocks.front().phase == Approx(10).epsilon(0.01));
  for (const auto& b : run.blocks) CHECK(b.energy_error < 1e-11);
  // The position error is the phase error's chord while the radius holds.
  CHECK(run.blocks.back().max_error == Approx(std::abs(run.blocks.back().phase)).epsilon(0.01));
}

TEST_CASE("the line fit recovers a + b x and its largest residual", "[analysis]") {
  std::vector<double> x, y;
  for (double v = 1e3; v <= 1e5; v += 1e3) x.push_back(v), y.push_back(2e-9 * v - 3e-7);
  Line fit = fit_line(x, y);
  CHECK(fit.slope == Approx(2e-9).epsilon(1e-10));
  CHECK(fit.intercept == Approx(-3e-7).epsilon(1e-8));
  CHECK(largest_residual(fit, x, y) < 1e-15);
  y[10] += 1e-6;  // one stray point
  fit = fit_line(x, y);
  CHECK(largest_residual(fit, x, y) == Approx(1e-6).epsilon(0.05));
}

TEST_CASE("each block's error is the largest distance from the exact circle's point over that block's steps", "[analysis]") {
  // Euler-Cromer at 50 steps an orbit: an error that swings and grows within
  // each orbit, measured here from its definition on the same run.
  const OrbitRun run = circular_orbit_run("euler-cromer", 50, 4, 1);
  REQUIRE(run.blocks.size() == 4);
  auto t = test::trajectory("two-body", {"scheme=euler-cromer", "steps_per_period=50", "periods=4"});
  std::vector<double> largest(4, 0.0);
  for (const auto& row : test::rows(*t)) {
    const long long step = std::llround(row[0] / run.dt);
    const size_t block = step == 0 ? 0 : size_t((step - 1) / 50);
    largest[std::min<size_t>(block, 3)] =
        std::max(largest[std::min<size_t>(block, 3)], std::hypot(row[1] - std::cos(row[0]), row[2] - std::sin(row[0])));
  }
  for (size_t i = 0; i < 4; ++i) CHECK(run.blocks[i].max_error == Approx(largest[i]).epsilon(1e-12));
}
