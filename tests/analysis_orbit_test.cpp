// The circular orbit of two-body (Exercise 1.28) and the power-law fit of its error growth.
#include <catch2/catch.hpp>
#include <cmath>
#include <ctime>

#include "core/analysis/orbit_error.hpp"
#include "core/analysis/power_law_fit.hpp"

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

TEST_CASE("the power-law fit recovers c x^p", "[analysis]") {
  std::vector<double> x, y;
  for (double v = 1e3; v <= 1e5; v *= 1.5) x.push_back(v), y.push_back(3e-7 * std::pow(v, 1.02));
  const PowerLaw fit = fit_power_law(x, y);
  CHECK(fit.exponent == Approx(1.02).epsilon(1e-10));
  CHECK(fit.coefficient == Approx(3e-7).epsilon(1e-8));
  CHECK(fit(1e9) == Approx(3e-7 * std::pow(1e9, 1.02)).epsilon(1e-8));
}
