// Properties of the chapter's models (docs/models.md).
#include <catch2/catch.hpp>
#include <cmath>

#include "core/error.hpp"
#include "test_support.hpp"

using namespace vibra;
using vibra::test::rows;
using vibra::test::trajectory;

TEST_CASE("pendulum: wire force and drag follow from theta and omega", "[models]") {
  for (std::string scheme : {"rk4", "centered", "staggered", "crank-nicolson"}) {
    auto r = rows(*trajectory("pendulum", {"alpha=0.4", "Theta=70", "scheme=" + scheme, "periods=2"}));
    for (auto& row : r) {
      const double theta = row[1], omega = row[2];
      CHECK(row[3] == Approx(omega * omega + std::cos(theta)).epsilon(1e-15));
      CHECK(row[4] == Approx(-0.4 * std::abs(omega) * omega).margin(1e-17));
    }
  }
}

TEST_CASE("pendulum: angles in degrees by default, radians with a suffix", "[models]") {
  CHECK(rows(*trajectory("pendulum", {"Theta=90", "T=0.1", "dt=0.1"}))[0][1] == Approx(M_PI / 2));
  CHECK(rows(*trajectory("pendulum", {"Theta=0.7rad", "T=0.1", "dt=0.1"}))[0][1] == Approx(0.7));
  CHECK(rows(*trajectory("pendulum", {"Theta=pi/4 rad", "T=0.1", "dt=0.1"}))[0][1] == Approx(M_PI / 4));
}

TEST_CASE("pendulum: alpha from physical data", "[models]") {
  // alpha = C_D rho pi R^2 L / (2 m): drag on a light bob damps faster.
  auto last_swing = [](const std::vector<std::vector<double>>& r) {
    double largest = 0;
    for (size_t i = r.size() * 2 / 3; i < r.size(); ++i) largest = std::max(largest, std::abs(r[i][1]));
    return largest;
  };
  auto light = rows(*trajectory("pendulum", {"L=1", "m=0.01", "R=0.05", "periods=3"}));
  auto heavy = rows(*trajectory("pendulum", {"L=1", "m=10", "R=0.05", "periods=3"}));
  CHECK(last_swing(light) < 0.5 * last_swing(heavy));
  CHECK_THROWS_AS(trajectory("pendulum", {"L=1", "m=1"}), UsageError);
  CHECK_THROWS_AS(trajectory("pendulum", {"L=1", "m=1", "R=0.1", "alpha=0.2"}), UsageError);
}

TEST_CASE("small-angle pendulum approaches Theta cos t", "[models]") {
  auto r = rows(*trajectory("pendulum", {"alpha=0", "Theta=0.5", "periods=2", "steps_per_period=200"}));
  const double Theta = 0.5 * M_PI / 180;
  // The nonlinear period is longer by about Theta^2/16: a phase lag of ~5e-7 here.
  for (auto& row : r) CHECK(row[1] == Approx(Theta * std::cos(row[0])).margin(2e-6));
}

TEST_CASE("physical pendulum of a point mass is the simple pendulum", "[models]") {
  auto simple = rows(*trajectory("pendulum", {"alpha=0", "Theta=50", "periods=2"}));
  auto rod = rows(*trajectory("physical-pendulum", {"m_rod=0", "m_bob=1", "R=0", "Theta=50", "periods=2"}));
  REQUIRE(simple.size() == rod.size());
  for (size_t i = 0; i < simple.size(); ++i)
    for (int c = 1; c < 5; ++c) CHECK(rod[i][c] == Approx(simple[i][c]).margin(1e-14));
}

TEST_CASE("elastic pendulum at rest stays exactly at rest", "[models]") {
  for (auto& row : rows(*trajectory("elastic-pendulum", {"Theta=0", "eps=0", "periods=3"})))
    for (int c = 1; c < 6; ++c) CHECK(row[c] == 0.0);
}

TEST_CASE("elastic pendulum: vertical oscillation y = -eps cos(sqrt(beta/(1-beta)) t)", "[models]") {
  const double beta = 0.9, eps = 0.1, w = std::sqrt(beta / (1 - beta));
  auto r = rows(*trajectory("elastic-pendulum", {"Theta=0", "eps=0.1", "beta=0.9", "steps_per_period=2000",
                                                 "periods=2"}));
  for (auto& row : r) {
    CHECK(row[1] == 0.0);
    CHECK(row[2] == Approx(-eps * std::cos(w * row[0])).margin(1e-8));
  }
}

TEST_CASE("elastic pendulum approaches the rigid pendulum as beta -> 1", "[models]") {
  // The pendulum mode has frequency sqrt(beta); time is scaled by sqrt(L0/g).
  const double beta = 0.999999;
  auto r = rows(*trajectory("elastic-pendulum", {"beta=" + test::str(beta), "Theta=10", "dt=0.0005", "T=3"}));
  auto rigid = rows(*trajectory("pendulum", {"alpha=0", "Theta=10", "dt=" + test::str(0.0005 * std::sqrt(beta)),
                                             "T=" + test::str(3 * std::sqrt(beta))}));
  REQUIRE(r.size() == rigid.size());
  for (size_t i = 0; i < r.size(); i += 100) CHECK(r[i][5] == Approx(rigid[i][1]).margin(1e-4));
}

TEST_CASE("two-body circular orbit keeps radius 1 and period 2 pi", "[models]") {
  auto r = rows(*trajectory("two-body", {"periods=3", "steps_per_period=400"}));
  for (auto& row : r) CHECK(std::hypot(row[1], row[2]) == Approx(1).epsilon(1e-8));
  CHECK(r.back()[0] == Approx(6 * M_PI));
  CHECK(r.back()[1] == Approx(1).epsilon(1e-7));
}

TEST_CASE("bad model settings are usage errors that name the fix", "[models]") {
  auto message = [](std::vector<std::string> settings, std::string model = "undamped") {
    try {
      trajectory(model, settings);
    } catch (const UsageError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  CHECK_THAT(message({"dt=0"}), Catch::Contains("dt=0 must be a positive"));
  CHECK_THAT(message({"T=-1"}), Catch::Contains("T=-1 must be a positive"));
  CHECK_THAT(message({"dt=0.5"}), Catch::Contains("above the stability limit 0.31831"));
  CHECK_THAT(message({"dt=abc"}), Catch::Contains("cannot read dt='abc'"));
  CHECK_THAT(message({"scheme=rk5"}), Catch::Contains("choose one of"));
  CHECK_THAT(message({"dt=0.1", "steps_per_period=10"}), Catch::Contains("not both"));
  CHECK_THAT(message({"scheme=centered-adjusted"}, "pendulum"), Catch::Contains("undamped only"));
  CHECK_THAT(message({"beta=1"}, "elastic-pendulum"), Catch::Contains("beta must be < 1"));
  CHECK_THAT(message({"s=sin(x)"}, "vibration"), Catch::Contains("cannot read s='sin(x)'"));
  CHECK_THAT(message({"s=0"}, "vibration"), Catch::Contains("give dt"));
  CHECK_THROWS_AS(trajectory("undamped", {"Tx=1"}), UsageError);
}

TEST_CASE("a blow-up stops with the step and time", "[models]") {
  auto t = trajectory("undamped", {"scheme=forward-euler", "dt=0.3", "T=1e5"});
  try {
    while (t->advance()) {
    }
    FAIL("no error");
  } catch (const SolutionError& e) {
    CHECK_THAT(e.what(), Catch::Contains("non-finite at step"));
  }
}
