// The RLC circuit (section 1.12.11): L q'' + R q' + q/C = V(t), I = q',
// against the free underdamped solution and the forced steady state.
#include <catch2/catch.hpp>
#include <cmath>

#include "test_support.hpp"

using vibra::test::rows;
using vibra::test::str;
using vibra::test::trajectory;

TEST_CASE("rlc: the free underdamped oscillation q0 e^{-at}(cos w_d t + a/w_d sin w_d t)", "[models][rlc]") {
  const double L = 0.5, R = 0.3, C = 0.2, q0 = 2e-3;
  const double a = R / (2 * L), wd = std::sqrt(1 / (L * C) - a * a);
  auto q_exact = [&](double t) { return q0 * std::exp(-a * t) * (std::cos(wd * t) + a / wd * std::sin(wd * t)); };
  auto I_exact = [&](double t) { return -q0 * std::exp(-a * t) * (a * a / wd + wd) * std::sin(wd * t); };
  double previous_error = 0;
  for (int steps : {100, 200, 400}) {
    auto run = trajectory("rlc", {"L=" + str(L), "R=" + str(R), "C=" + str(C), "q0=" + str(q0), "scheme=rk4",
                                  "steps_per_period=" + std::to_string(steps), "periods=5"});
    REQUIRE(run->info().exact);
    CHECK(run->info().mesh.period == Approx(2 * M_PI * std::sqrt(L * C)));
    double error = 0;
    for (const auto& row : rows(*run)) {
      CHECK(run->info().exact(row[0]) == Approx(q_exact(row[0])).margin(1e-15));
      error = std::max({error, std::abs(row[1] - q_exact(row[0])) / q0, std::abs(row[2] - I_exact(row[0])) / (q0 * wd)});
      CHECK(row[3] == 0);
    }
    // RK4: the error falls 16-fold when dt halves.
    if (previous_error > 0) CHECK(previous_error / error == Approx(16).epsilon(0.1));
    previous_error = error;
  }
  CHECK(previous_error < 1e-8);
}

TEST_CASE("rlc: a sine source drives the steady state V0 sin(w t - phi)/Z", "[models][rlc]") {
  const double L = 1, R = 0.8, C = 0.25, V0 = 3, w = 1.3;
  // Impedance for the charge: |1/C - L w^2 + i R w|; phase of the charge behind V.
  const double reactance = 1 / C - L * w * w, Z = std::hypot(reactance, R * w), phi = std::atan2(R * w, reactance);
  auto q_steady = [&](double t) { return V0 / Z * std::sin(w * t - phi); };
  auto run = trajectory("rlc", {"L=1", "R=" + str(R), "C=" + str(C), "q0=0", "V=" + str(V0) + "*sin(" + str(w) + "*t)",
                                "scheme=rk4", "dt=0.005", "T=60"});
  CHECK_FALSE(run->info().exact);
  double worst = 0;
  for (const auto& row : rows(*run)) {
    CHECK(row[3] == Approx(V0 * std::sin(w * row[0])).margin(1e-12));
    // The transient e^{-R t/(2L)} is below 1e-9 after t = 52.
    if (row[0] > 52) worst = std::max(worst, std::abs(row[1] - q_steady(row[0])));
  }
  CHECK(worst < 1e-8);
}

TEST_CASE("rlc: bad keys are refused", "[models][rlc]") {
  CHECK_THROWS_WITH(trajectory("rlc", {"R=-1"}), Catch::Contains("R=-1"));
  CHECK_THROWS_WITH(trajectory("rlc", {"C=0"}), Catch::Contains("C"));
  CHECK_THROWS_WITH(trajectory("rlc", {"L=-2"}), Catch::Contains("L"));
}
