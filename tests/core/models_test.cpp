// Properties of the chapter's models (docs/models.md).
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>

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

TEST_CASE("physical pendulum of a rod and a bob: wire force M L_cm^2/I omega^2 + cos theta, drag c/I |omega| omega", "[models]") {
  // A uniform rod of 2 kg and 1.5 m with a 0.5 kg bob at its end, about the
  // rod's end: I = m_rod L^2/3 + m_bob L^2, the centre of mass at
  // L_cm = (m_rod L/2 + m_bob L)/M, the drag torque c = C_D rho pi R^2 L^3 / 2.
  const double L = 1.5, m_rod = 2, m_bob = 0.5, R = 0.05, C_D = 0.4, rho = 1.2, M = m_rod + m_bob;
  const double I = m_rod * L * L / 3 + m_bob * L * L, L_cm = (m_rod * L / 2 + m_bob * L) / M;
  const double wire = M * L_cm * L_cm / I, alpha = 0.5 * C_D * rho * M_PI * R * R * L * L * L / I;
  REQUIRE(wire == Approx(2.025 / 2.625));
  auto r = rows(*trajectory("physical-pendulum", {"L=1.5", "m_rod=2", "m_bob=0.5", "R=0.05", "Theta=80", "periods=2"}));
  for (auto& row : r) {
    const double theta = row[1], omega = row[2];
    CHECK(row[3] == Approx(wire * omega * omega + std::cos(theta)).epsilon(1e-14));
    CHECK(row[4] == Approx(-alpha * std::abs(omega) * omega).margin(1e-17));
  }
  // A rod alone: three quarters of omega^2 in the wire force.
  for (auto& row : rows(*trajectory("physical-pendulum", {"m_bob=0", "Theta=30", "periods=1"})))
    CHECK(row[3] == Approx(0.75 * row[2] * row[2] + std::cos(row[1])).epsilon(1e-14));
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

TEST_CASE("two-body circular orbits either way round: the exact x(t) follows the planet from any start", "[models]") {
  // A circular orbit of radius r has speed r^(-1/2) and period 2 pi r^(3/2);
  // started at angle phi, x(t) = r cos(phi + s t / r^(3/2)), s = +1
  // counterclockwise and -1 clockwise.
  for (double r : {1.0, 2.0})
    for (double phi : {0.0, 1.0, 2.5, -2.0})
      for (int sense : {1, -1}) {
        const double speed = 1 / std::sqrt(r);
        char settings[4][64];
        std::snprintf(settings[0], 64, "x0=%.17g", r * std::cos(phi));
        std::snprintf(settings[1], 64, "y0=%.17g", r * std::sin(phi));
        std::snprintf(settings[2], 64, "vx0=%.17g", -sense * speed * std::sin(phi));
        std::snprintf(settings[3], 64, "vy0=%.17g", sense * speed * std::cos(phi));
        auto t = trajectory("two-body", {settings[0], settings[1], settings[2], settings[3], "scheme=rk4",
                                         "steps_per_period=400", "periods=1"});
        INFO("r = " << r << ", phi = " << phi << ", sense " << sense);
        REQUIRE(t->info().exact);
        CHECK(t->info().exact_period == Approx(2 * M_PI * std::pow(r, 1.5)));
        for (auto& row : rows(*t)) {
          CHECK(t->info().exact(row[0]) == Approx(r * std::cos(phi + sense * row[0] / std::pow(r, 1.5))).margin(1e-12));
          CHECK(t->info().exact(row[0]) == Approx(row[1]).margin(1e-7 * r));
        }
      }
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

TEST_CASE("above the stability limit: the advice names the limit and the fewest steps per period that are stable", "[models]") {
  // On undamped (w = 2 pi, period 1): the centered family is stable for
  // w dt <= 2 (1.23), RK4 up to 2 sqrt(2), RK3 up to sqrt(3), AB3 up to 0.7236.
  const double w = 2 * M_PI;
  const std::pair<const char*, double> limits[] = {
      {"centered", 2}, {"euler-cromer", 2}, {"rk4", 2 * std::sqrt(2.0)}, {"rk3", std::sqrt(3.0)}, {"ab3", 0.7236}};
  for (const auto& [scheme, limit] : limits) {
    INFO(scheme);
    std::string message;
    try {
      trajectory("undamped", {std::string("scheme=") + scheme, "dt=3"});
    } catch (const UsageError& e) {
      message = e.what();
    }
    double advised_dt = 0, advised_steps = 0;
    const size_t at = message.find("use dt <= ");
    REQUIRE(at != std::string::npos);
    REQUIRE(std::sscanf(message.c_str() + at, "use dt <= %lf (steps_per_period >= %lf)", &advised_dt, &advised_steps) == 2);
    CHECK(advised_dt == Approx(limit / w).epsilon(1e-5));
    CHECK(advised_steps == std::ceil(w / limit));
    // The advice works, and is the fewest steps that do.
    const std::string steps = "steps_per_period=" + std::to_string(int(advised_steps));
    CHECK_NOTHROW(trajectory("undamped", {std::string("scheme=") + scheme, steps}));
    CHECK_THROWS_AS(trajectory("undamped", {std::string("scheme=") + scheme,
                                            "steps_per_period=" + std::to_string(int(advised_steps) - 1)}),
                    UsageError);
  }
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
