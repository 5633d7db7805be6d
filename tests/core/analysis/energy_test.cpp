// The energy-error table of the book (the table after (1.49); docs/analysis.md).
#include <catch2/catch.hpp>

#include <cmath>

#include "core/analysis/energy.hpp"
#include "test_support.hpp"

using namespace vibra;

TEST_CASE("max relative energy errors match the book's table within 1%", "[energy]") {
  struct Row {
    const char* scheme;
    double T, dt, expected;
  };
  const Row table[] = {
      {"forward-euler", 1, 0.025, 1.678e0},       {"backward-euler", 1, 0.025, 6.235e-1},
      {"crank-nicolson", 1, 0.025, 1.221e-2},     {"rk2", 1, 0.025, 6.076e-3},
      {"rk4", 1, 0.025, 8.214e-3},                {"forward-euler", 10, 0.05, 1.120e8},
      {"forward-euler", 10, 0.025, 1.788e4},      {"forward-euler", 10, 0.0125, 1.374e2},
      {"crank-nicolson", 10, 0.05, 4.756e-2},     {"crank-nicolson", 10, 0.025, 1.221e-2},
      {"rk2", 10, 0.05, 6.152e-1},
      {"rk2", 10, 0.025, 6.250e-2},               {"rk2", 10, 0.0125, 7.631e-3},
      {"rk4", 10, 0.05, 3.510e-2},                {"rk4", 10, 0.025, 8.288e-3},
      {"rk4", 10, 0.0125, 2.058e-3},              {"euler-cromer", 10, 0.05, 2.530e-2},
      {"euler-cromer", 10, 0.025, 6.206e-3},      {"euler-cromer", 10, 0.0125, 1.544e-3},
  };
  for (const Row& row : table) {
    INFO(row.scheme << " T=" << row.T << " dt=" << row.dt);
    auto t = test::trajectory("undamped", {std::string("scheme=") + row.scheme, "T=" + test::str(row.T),
                                           "dt=" + test::str(row.dt)});
    CHECK(max_relative_energy_error(*t, 2 * M_PI, 1, 0) == Approx(row.expected).epsilon(0.01));
  }
}

TEST_CASE("Crank-Nicolson at dt = 0.0125 reaches the analytic bound, below the book's 3.125e-3", "[energy]") {
  // CN is exact in energy for (u, v); the error is that of the centered
  // difference: sin^2(w~ dt)/(w dt)^2 - 1 with w~ dt = 2 atan(w dt/2). That
  // gives 3.075e-3; the book's 3.125e-3 (1.6% higher) came from Odespy's
  // Newton iteration stopping at a loose tolerance.
  const double wdt = 2 * M_PI * 0.0125, bound = 1 - std::pow(std::sin(2 * std::atan(wdt / 2)) / wdt, 2);
  auto t = test::trajectory("undamped", {"scheme=crank-nicolson", "T=10", "dt=0.0125"});
  const double measured = max_relative_energy_error(*t, 2 * M_PI, 1, 0);
  CHECK(measured == Approx(bound).epsilon(0.01));
  CHECK(measured == Approx(3.125e-3).epsilon(0.02));
}
