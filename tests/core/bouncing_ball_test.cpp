// The bouncing ball (section 1.12.9, Exercise 1.24): impacts located inside
// the step against the closed-form impact times, speeds and apex heights.
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <sstream>

#include "cli_support.hpp"
#include "core/error.hpp"
#include "core/event_trajectory.hpp"
#include "test_support.hpp"

using namespace vibra;
using vibra::test::rows;
using vibra::test::str;
using vibra::test::trajectory;

namespace {
// Every scheme whose step is exact for h'' = -g.
const char* kExactSchemes[] = {"centered", "backward-damping", "euler-cromer-half", "staggered", "velocity-verlet",
                               "pefrl",    "rk2",              "rk4",               "crank-nicolson"};

struct Run {
  std::vector<EventTrajectory::Event> impacts;
  std::vector<std::vector<double>> rows;
};

Run bounce(const std::vector<std::string>& settings) {
  auto run = trajectory("bouncing-ball", settings);
  auto* events = dynamic_cast<EventTrajectory*>(run.get());
  REQUIRE(events != nullptr);
  Run out;
  events->on_event([&](const EventTrajectory::Event& e) { out.impacts.push_back(e); });
  out.rows = rows(*run);
  return out;
}
}  // namespace

TEST_CASE("bouncing ball: impact times, speeds and apexes as the formulas say, with every exact scheme",
          "[models][bouncing-ball]") {
  const double h0 = 1.3, g = 9.81, C_R = 0.7, eps_v = 0.05;
  const double t1 = std::sqrt(2 * h0 / g), v1 = std::sqrt(2 * g * h0);
  for (const char* scheme : kExactSchemes) {
    // 100 steps per period: the first impact falls on a mesh point.
    for (const char* steps : {"7", "40", "100", "333"}) {
      INFO(scheme << ", " << steps << " steps per period");
      const Run r = bounce({"h0=" + str(h0), "C_R=" + str(C_R), "eps_v=" + str(eps_v), std::string("scheme=") + scheme,
                            std::string("steps_per_period=") + steps, "periods=12"});
      // The rebound speeds v1 C_R^n: rest at the first below eps_v.
      size_t expected = 1;
      while (v1 * std::pow(C_R, double(expected)) >= eps_v) ++expected;
      REQUIRE(r.impacts.size() == expected);
      double t_n = t1;
      for (size_t i = 0; i < r.impacts.size(); ++i) {
        const double n = double(i + 1), speed = v1 * std::pow(C_R, n - 1);
        CHECK(r.impacts[i].t == Approx(t_n).epsilon(1e-9));
        CHECK(r.impacts[i].v_before == Approx(-speed).epsilon(1e-9));
        const bool last = i + 1 == r.impacts.size();
        if (last) CHECK(r.impacts[i].v_after == 0);
        else CHECK(r.impacts[i].v_after == Approx(C_R * speed).epsilon(1e-9));
        if (!last) CHECK(r.impacts[i].v_after * r.impacts[i].v_after / (2 * g) ==
                         Approx(std::pow(C_R, 2 * n) * h0).epsilon(1e-9));
        t_n += 2 * C_R * speed / g;
      }
      // Never below the ground; at rest from the last impact on, exactly.
      const double t_rest = r.impacts.back().t;
      for (const auto& row : r.rows) {
        CHECK(row[1] >= 0);
        if (row[0] >= t_rest) CHECK((row[1] == 0 && row[2] == 0));
      }
    }
  }
}

TEST_CASE("bouncing ball: the rows follow the exact height between impacts", "[models][bouncing-ball]") {
  auto run = trajectory("bouncing-ball", {"h0=2", "V=1.5", "steps_per_period=13", "scheme=velocity-verlet"});
  const auto exact = run->info().exact;
  REQUIRE(exact);
  const double g = model_parameters(find_model("bouncing-ball")).number("g"), dt = run->info().mesh.dt;
  std::vector<double> a(run->width()), b(run->width()), row(run->width());
  double worst = 0;
  int impacts = 0;
  run->row(a);
  while (!run->done()) {
    worst = std::max(worst, std::abs(a[1] - exact(a[0])));
    // Frames between steps: the straight line between the mesh values, turned
    // at an impact inside the step (its knot on the ground), never below it.
    const double t = a[0] + 0.37 * run->info().mesh.dt;
    run->advance();
    run->row(b);
    run->row_at(t, row);
    CHECK(row[1] >= 0);
    // Free fall for the whole step leaves v - g dt (velocity Verlet is exact for it); else an impact or rest came in it.
    if (std::abs(b[2] - (a[2] - g * dt)) > 1e-9) {
      ++impacts;
      CHECK(row[1] <= std::max(a[1], b[1]) + 1e-12);
    } else {
      CHECK(row[1] == Approx(a[1] + 0.37 * (b[1] - a[1])).margin(1e-12));
    }
    a = b;
  }
  CHECK(impacts > 0);
  CHECK(worst < 1e-9);
}

TEST_CASE("bouncing ball: a start on the ground", "[models][bouncing-ball]") {
  for (const auto& row : bounce({"h0=0", "dt=0.01", "T=1"}).rows) CHECK((row[1] == 0 && row[2] == 0));
  // Thrown down from the ground: it rebounds at once with C_R |V|.
  const Run r = bounce({"h0=0", "V=-2", "C_R=0.5", "g=10", "T=0.21", "dt=0.01"});
  CHECK(r.rows[0][2] == Approx(1));
  REQUIRE(r.impacts.size() >= 1);
  CHECK(r.impacts[0].t == Approx(0.2).epsilon(1e-9));
}

TEST_CASE("bouncing ball thrown up: its height bound is the apex h0 + V^2/(2g), its period the fall and rise from it",
          "[models][bouncing-ball]") {
  // Thrown up at 3 m/s from 1 m with g = 10: the apex is 1 + 9/20 = 1.45 m,
  // reached at t = 0.3; a fall from there and the rise back take
  // 2 sqrt(2 * 1.45 / 10), and the run's default length is 6 of them.
  const double apex = 1.45, period = 2 * std::sqrt(2 * apex / 10);
  auto run = trajectory("bouncing-ball", {"h0=1", "V=3", "g=10", "dt=0.001"});
  CHECK(run->info().amplitude_bound == Approx(apex).epsilon(1e-12));
  CHECK(run->info().mesh.T == Approx(6 * period).margin(0.001));  // within a step: T is a whole number of them
  double highest = 0;
  for (const auto& row : rows(*run)) highest = std::max(highest, row[1]);
  CHECK(highest == Approx(apex).epsilon(1e-6));  // the rows reach the bound and no higher
  CHECK(highest <= apex + 1e-12);
}

TEST_CASE("bouncing ball: first-order schemes and bad keys are refused", "[models][bouncing-ball]") {
  for (const char* scheme : {"forward-euler", "backward-euler", "euler-cromer"})
    CHECK_THROWS_WITH(trajectory("bouncing-ball", {std::string("scheme=") + scheme}),
                      Catch::Contains("does not integrate free fall exactly"));
  CHECK_THROWS_WITH(trajectory("bouncing-ball", {"C_R=1"}), Catch::Contains("C_R=1"));
  CHECK_THROWS_WITH(trajectory("bouncing-ball", {"h0=-1"}), Catch::Contains("h0=-1"));
  CHECK_THROWS_WITH(trajectory("bouncing-ball", {"eps_v=0"}), Catch::Contains("eps_v"));
}

TEST_CASE("vibra analyze bounces lists every impact", "[cli][bouncing-ball]") {
  const auto result = vibra::test::run_vibra("analyze bounces --set C_R=0.5 --set eps_v=0.5 --set h0=1 --csv");
  REQUIRE(result.exit_code == 0);
  // v1 = sqrt(2 g) = 4.43: rebounds 2.21, 1.11, 0.55, then 0.28 < 0.5 rests.
  std::istringstream lines(result.out);
  std::string line;
  std::vector<std::string> table;
  while (std::getline(lines, line)) table.push_back(line);
  REQUIRE(table.size() == 5);
  CHECK(table[0] == "n,t,v_before,v_after,h_apex");
  double n, t, before, after, apex;
  REQUIRE(std::sscanf(table[2].c_str(), "%lf,%lf,%lf,%lf,%lf", &n, &t, &before, &after, &apex) == 5);
  const double t1 = std::sqrt(2 / 9.81);
  CHECK(n == 2);
  CHECK(t == Approx(t1 + 2 * 0.5 * t1).epsilon(1e-6));
  CHECK(after == Approx(0.25 * std::sqrt(2 * 9.81)).epsilon(1e-6));
  CHECK(apex == Approx(0.0625).epsilon(1e-6));
  CHECK_THAT(table[4], Catch::StartsWith("4,") && Catch::EndsWith(",0,0"));
}
