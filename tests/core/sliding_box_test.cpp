// The sliding box with Coulomb friction (section 1.12.3): turning points
// located inside the step, exact rest, and the linear spring's rule.
#include <catch2/catch.hpp>
#include <cmath>

#include "core/error.hpp"
#include "core/event_trajectory.hpp"
#include "core/models/sliding_box_law.hpp"
#include "test_support.hpp"

using namespace vibra;
using vibra::test::rows;
using vibra::test::str;
using vibra::test::trajectory;

namespace {
const char* kSchemes[] = {"centered", "euler-cromer", "euler-cromer-half", "staggered", "velocity-verlet",
                          "pefrl",    "rk2",          "rk4",               "crank-nicolson"};

/// Turning points (t, u) of a run, from the trajectory's event record.
std::vector<EventTrajectory::Event> turning_points(const std::vector<std::string>& settings) {
  auto run = trajectory("sliding-box", settings);
  auto* events = dynamic_cast<EventTrajectory*>(run.get());
  REQUIRE(events != nullptr);
  std::vector<EventTrajectory::Event> out;
  events->on_event([&](const EventTrajectory::Event& e) { out.push_back(e); });
  while (run->advance()) {
  }
  return out;
}
}  // namespace

TEST_CASE("sliding box, linear spring: half swings of length pi, |u| shrinks by 2 mu, rest at |u| <= mu",
          "[models][sliding-box]") {
  for (double mu : {0.05, 0.08, 0.13, 0.3}) {
    for (const char* scheme : kSchemes) {
      INFO("mu = " << mu << ", scheme " << scheme);
      const auto events = turning_points({"mu=" + str(mu), std::string("scheme=") + scheme, "steps_per_period=200",
                                          "periods=8"});
      // The rule: amplitudes 1, 1 - 2 mu, 1 - 4 mu, ... alternating sign,
      // each reached pi after the one before; the last is inside the band.
      double amplitude = 1;
      size_t expected = 0;
      while (amplitude > mu) amplitude -= 2 * mu, ++expected;
      REQUIRE(events.size() == expected);
      const double tolerance = std::string(scheme).find("euler-cromer") == 0 && std::string(scheme).size() == 12
                                   ? 5e-2 : 2e-3;  // first-order Euler-Cromer
      for (size_t i = 0; i < events.size(); ++i) {
        const double a = (1 - 2 * mu * (i + 1)) * (i % 2 == 0 ? -1 : 1);
        CHECK(events[i].t == Approx(M_PI * (i + 1)).margin(tolerance * 3));
        CHECK(events[i].u == Approx(a).margin(tolerance));
        CHECK(events[i].v_after == 0);
      }
      CHECK(std::abs(events.back().u) <= mu + tolerance);
    }
  }
}

TEST_CASE("sliding box: at rest it stays exactly at rest, and the exact solution is followed",
          "[models][sliding-box]") {
  auto run = trajectory("sliding-box", {"mu=0.2", "steps_per_period=100", "periods=6"});
  const auto exact = run->info().exact;
  REQUIRE(exact);
  const auto r = rows(*run);
  // mu = 0.2: 1 -> -0.6 -> 0.2 (inside the band): rest after two half swings.
  const auto& last = r.back();
  CHECK(last[2] == 0);
  for (const auto& row : r) {
    CHECK(row[1] == Approx(exact(row[0])).margin(1e-3));
    if (row[0] > 2 * M_PI + 1e-9) {
      CHECK(row[2] == 0);
      CHECK(row[1] == last[1]);  // not a single bit of creep
    }
  }
  CHECK(last[1] == Approx(0.2).margin(1e-3));
}

TEST_CASE("sliding box: a start inside the friction band never moves", "[models][sliding-box]") {
  for (const char* scheme : kSchemes) {
    INFO(scheme);
    for (const auto& row : rows(*trajectory("sliding-box", {"mu=0.5", "I=0.4", std::string("scheme=") + scheme})))
      CHECK((row[1] == 0.4 && row[2] == 0));
  }
  // With the tanh spring the band is |tanh(alpha u)/alpha| <= mu.
  for (const auto& row : rows(*trajectory("sliding-box", {"mu=0.3", "alpha=2", "I=0.3"}))) CHECK(row[1] == 0.3);
}

TEST_CASE("sliding box: the energy never increases, with any scheme that is stable", "[models][sliding-box]") {
  for (const char* alpha : {"0", "1.5"}) {
    for (const char* scheme : {"centered", "staggered", "rk4", "pefrl", "crank-nicolson", "velocity-verlet"}) {
      INFO(scheme << ", alpha " << alpha);
      SlidingBoxLaw law;
      law.mu = 0.07, law.alpha = std::stod(alpha);
      double previous = 1e300;
      for (const auto& row : rows(*trajectory("sliding-box", {"mu=0.07", std::string("alpha=") + alpha,
                                                              std::string("scheme=") + scheme, "steps_per_period=400"}))) {
        const double energy = 0.5 * row[2] * row[2] + law.potential(row[1]);
        CHECK(energy <= previous * (1 + 1e-6) + 1e-9);
        previous = energy;
      }
    }
  }
}

TEST_CASE("sliding box: no chatter at coarse dt, rows between steps stay on the right side", "[models][sliding-box]") {
  // 12 steps per period: the naive sign() would flip the friction back and forth about v = 0.
  auto run = trajectory("sliding-box", {"mu=0.08", "steps_per_period=12", "periods=6"});
  int sign_changes = 0;
  double previous_v = 0;
  std::vector<double> row(run->width()), mid(run->width());
  do {
    run->row(row);
    if (row[2] * previous_v < 0) ++sign_changes;
    if (row[2] != 0) previous_v = row[2];
  } while (run->advance());
  CHECK(sign_changes <= 6);  // six turning points: 1, 0.84, ..., 0.04
}

TEST_CASE("sliding box: bad keys are refused with the key named", "[models][sliding-box]") {
  CHECK_THROWS_WITH(trajectory("sliding-box", {"mu=-1"}), Catch::Contains("mu=-1"));
  CHECK_THROWS_WITH(trajectory("sliding-box", {"alpha=-2"}), Catch::Contains("alpha"));
}
