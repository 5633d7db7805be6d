// The elastic pendulum (1.148): the book's period P = 2 pi for the time keys
// (Exercise 1.26) and its energy, conserved without drag.
#include <catch2/catch.hpp>
#include <cmath>

#include "test_support.hpp"

using vibra::test::rows;
using vibra::test::str;
using vibra::test::trajectory;

namespace {
/// 0.5 |v|^2 + beta y + 0.5 beta/(1 - beta) (L - beta)^2, in units of m g (L0 + mg/k).
double energy(const std::vector<double>& row, double beta) {
  const double x = row[1], y = row[2], L = std::hypot(x, y - 1);
  return 0.5 * (row[3] * row[3] + row[4] * row[4]) + beta * y + 0.5 * beta / (1 - beta) * (L - beta) * (L - beta);
}
}  // namespace

TEST_CASE("elastic pendulum: the book's run, 600 steps per period of 2 pi, 3 periods", "[models][elastic-pendulum]") {
  auto run = trajectory("elastic-pendulum", {"beta=0.9", "Theta=30", "steps_per_period=600", "periods=3"});
  CHECK(run->info().mesh.period == Approx(2 * M_PI).epsilon(1e-15));
  CHECK(run->info().mesh.dt == Approx(2 * M_PI / 600).epsilon(1e-15));
  CHECK(run->info().mesh.steps == 1800);
  CHECK(rows(*run).back()[0] == Approx(6 * M_PI).epsilon(1e-12));
}

TEST_CASE("elastic pendulum: energy conserved without drag to the scheme's order", "[models][elastic-pendulum]") {
  const double beta = 0.8;
  for (auto [scheme, order] : {std::pair{"rk4", 4}, std::pair{"velocity-verlet", 2}}) {
    double previous = 0;
    for (int steps : {200, 400}) {
      INFO(scheme << ", " << steps << " steps per period");
      auto r = rows(*trajectory("elastic-pendulum", {"beta=" + str(beta), "Theta=40", "eps=0.1", std::string("scheme=") + scheme,
                                                     "steps_per_period=" + std::to_string(steps), "periods=4"}));
      const double e0 = energy(r[0], beta);
      double drift = 0;
      for (const auto& row : r) drift = std::max(drift, std::abs(energy(row, beta) - e0));
      CHECK(drift < 1e-3 * std::abs(e0 - energy({0, 0, 0, 0, 0}, beta)));
      if (previous > 0) CHECK(std::log2(previous / drift) > order - 0.3);  // rk4 does better here
      previous = drift;
    }
  }
  // With drag the energy only falls.
  auto r = rows(*trajectory("elastic-pendulum", {"beta=0.8", "Theta=40", "gamma=0.2", "steps_per_period=400"}));
  for (size_t i = 1; i < r.size(); ++i) CHECK(energy(r[i], 0.8) <= energy(r[i - 1], 0.8) + 1e-8);
}

namespace {
/// Checks a run's theta column against its positions, row by row, and
/// returns the largest |theta| it reaches.
double largest_theta(const std::string& release) {
  INFO(release);
  const auto r = rows(*trajectory("elastic-pendulum", {"beta=0.8", release, "eps=0.2"}));
  // The wire turns at |r x v| / r^2 <= |v| / r: no step turns it further than that allows.
  auto turn_rate = [](const std::vector<double>& row) { return std::hypot(row[3], row[4]) / std::hypot(row[1], row[2] - 1); };
  double largest = 0;
  for (size_t i = 0; i < r.size(); ++i) {
    const double x = r[i][1], y = r[i][2], theta = r[i][5];
    // The bob at (x, y) hangs at theta from the downward vertical at the pivot (0, 1).
    CHECK(std::remainder(theta - std::atan2(x, 1 - y), 2 * M_PI) == Approx(0).margin(1e-12));
    largest = std::max(largest, std::abs(theta));
    if (i == 0) continue;
    const double dt = r[i][0] - r[i - 1][0];
    CHECK(std::abs(theta - r[i - 1][5]) <= 1.5 * dt * std::max(turn_rate(r[i]), turn_rate(r[i - 1])));
  }
  return largest;
}
}  // namespace

TEST_CASE("elastic pendulum: theta is the wire's angle over all four quadrants, continuous, counting whole turns",
          "[models][elastic-pendulum]") {
  // Released level with the pivot and stretched (eps = 0.2), the bob is flung
  // up above it, past 90 degrees; released at 170 degrees it goes over the
  // top, turn after turn: theta passes 90 and 180 degrees without a jump.
  CHECK(largest_theta("Theta=90") > M_PI / 2);
  CHECK(largest_theta("Theta=170") > M_PI);
}
