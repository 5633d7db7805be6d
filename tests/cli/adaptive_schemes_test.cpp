// The adaptive schemes rkf45 and dopri5 (docs/schemes.md): the error follows
// the tolerance, the step count grows like tol^(-1/5), dopri5's dense output
// joins its steps and is as accurate between them, the run ends exactly at
// T, and every model runs with them.
#include <catch2/catch.hpp>
#include <cmath>

#include "cli_support.hpp"
#include "test_support.hpp"

using namespace vibra;
using vibra::test::rows;
using vibra::test::run_vibra;
using vibra::test::str;
using vibra::test::trajectory;

namespace {
struct AdaptiveRun {
  double max_error = 0;  ///< max |u - cos(2 pi t)| over the samples
  long long steps = 0;
  double end = 0;
};

/// u'' + (2 pi)^2 u = 0, u(0) = 1 over 10 periods, atol well below rtol so
/// that the relative tolerance decides.
AdaptiveRun undamped_run(const std::string& scheme, double rtol) {
  auto run = trajectory("undamped", {"scheme=" + scheme, "rtol=" + str(rtol), "atol=" + str(rtol * 1e-3), "T=10"});
  AdaptiveRun r;
  for (const auto& row : rows(*run)) {
    r.max_error = std::max(r.max_error, std::abs(row[1] - std::cos(2 * M_PI * row[0])));
    r.end = row[0];
  }
  r.steps = run->index();
  return r;
}
}  // namespace

TEST_CASE("adaptive schemes: the error follows rtol from 1e-4 to 1e-12, steps grow like tol^(-1/5)",
          "[schemes][adaptive]") {
  for (const char* scheme : {"rkf45", "dopri5"}) {
    double sum_x = 0, sum_y = 0, sum_xx = 0, sum_xy = 0;
    int n = 0;
    for (double rtol : {1e-4, 1e-6, 1e-8, 1e-10, 1e-12}) {
      const AdaptiveRun r = undamped_run(scheme, rtol);
      INFO(scheme << " rtol=" << rtol << ": error " << r.max_error << " in " << r.steps << " steps");
      CHECK(r.end == 10);  // the last step lands on T
      // Within a small factor of the tolerance: the error, a phase error
      // growing linearly, stays below 3 rtol per period, and is not so far
      // below the tolerance that the tolerance would not be what decides.
      CHECK(r.max_error < 3 * rtol * 10);
      CHECK(r.max_error > rtol / 1000);
      const double x = std::log(rtol), y = std::log(double(r.steps));
      sum_x += x, sum_y += y, sum_xx += x * x, sum_xy += x * y, ++n;
    }
    const double slope = (n * sum_xy - sum_x * sum_y) / (n * sum_xx - sum_x * sum_x);
    INFO(scheme << ": steps grow like rtol^" << slope);
    CHECK(slope == Approx(-0.2).margin(0.03));
  }
}

TEST_CASE("dopri5's dense output joins its steps and is as accurate between them", "[schemes][adaptive]") {
  auto run = trajectory("undamped", {"scheme=dopri5", "rtol=1e-8", "atol=1e-11", "T=3"});
  std::vector<double> previous(run->width()), current(run->width()), between(run->width());
  run->row(previous);
  double jump = 0, error_at_steps = 0, error_between = 0;
  long long steps = 0;
  while (run->advance()) {
    run->row(current);
    const double t0 = previous[0], t1 = current[0];
    // Continuity: at both ends of the step the interpolant is the sample.
    for (double t : {t0 + 1e-12 * (t1 - t0), t1 - 1e-12 * (t1 - t0)}) {
      run->row_at(t, between);
      const auto& end = t - t0 < t1 - t ? previous : current;
      jump = std::max({jump, std::abs(between[1] - end[1]), std::abs(between[2] - end[2])});
    }
    for (double s : {0.25, 0.5, 0.75}) {
      const double t = t0 + s * (t1 - t0);
      run->row_at(t, between);
      CHECK(between[0] == t);
      error_between = std::max(error_between, std::abs(between[1] - std::cos(2 * M_PI * t)));
    }
    error_at_steps = std::max(error_at_steps, std::abs(current[1] - std::cos(2 * M_PI * t1)));
    previous = current;
    ++steps;
  }
  INFO(steps << " steps; jump " << jump << "; error at steps " << error_at_steps << ", between " << error_between);
  CHECK(steps > 20);
  CHECK(jump < 1e-9);
  CHECK(error_between < 3 * error_at_steps + 1e-8);
  CHECK(error_between < 1e-6);
}

TEST_CASE("every model runs with the adaptive schemes", "[schemes][adaptive]") {
  struct Case {
    const char* model;
    std::vector<std::string> settings;
  };
  const Case cases[] = {
      {"undamped", {}},
      {"vibration", {"damping=quadratic", "b=0.3", "s=sin(u)", "F=0.1*cos(t)"}},
      {"pendulum", {"alpha=0.4", "Theta=70"}},
      {"physical-pendulum", {}},
      {"elastic-pendulum", {"Theta=30"}},
      {"two-body", {}},
      {"resonance", {}},
      {"sliding-box", {}},
      {"bumpy-road", {}},
      {"bouncing-ball", {}},
      {"rlc", {}},
  };
  for (const char* scheme : {"rkf45", "dopri5"})
    for (const Case& c : cases) {
      INFO(c.model << " with " << scheme);
      auto settings = c.settings;
      settings.push_back(std::string("scheme=") + scheme);
      auto run = trajectory(c.model, settings);
      const double T = run->info().mesh.T;
      double last = -1;
      bool increasing = true;
      for (const auto& row : rows(*run)) increasing &= row[0] > last, last = row[0];
      CHECK(increasing);
      CHECK(last == Approx(T).epsilon(1e-12));
    }
}

TEST_CASE("the bouncing ball's impacts are as exact with dopri5 as with the centered scheme", "[schemes][adaptive]") {
  // From rest at h0 = 1 with g = 9.81: first impact at sqrt(2 h0 / g).
  const auto r = run_vibra("analyze bounces --set scheme=dopri5 --csv");
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  const auto table = vibra::test::csv_rows(r.out);
  REQUIRE(table.size() >= 3);
  const auto& header = table[0];
  const auto t_column = std::find(header.begin(), header.end(), "t") - header.begin();
  REQUIRE(t_column < static_cast<long>(header.size()));
  CHECK(std::stod(table[1][t_column]) == Approx(std::sqrt(2 / 9.81)).epsilon(1e-9));
}

TEST_CASE("vibra solve prints an adaptive run's uneven times, ending at T", "[schemes][adaptive][cli]") {
  const auto r = run_vibra("solve undamped --set scheme=dopri5 --set T=2");
  REQUIRE(r.exit_code == 0);
  const auto table = vibra::test::csv_rows(r.out);
  REQUIRE(table.size() > 10);
  CHECK(table[0] == std::vector<std::string>{"t", "u", "v"});
  double smallest = INFINITY, largest = 0;
  for (size_t i = 2; i + 1 < table.size(); ++i) {
    const double dt = std::stod(table[i][0]) - std::stod(table[i - 1][0]);
    smallest = std::min(smallest, dt), largest = std::max(largest, dt);
  }
  CHECK(largest > 1.05 * smallest);  // uneven
  CHECK(std::stod(table.back()[0]) == 2);
}

TEST_CASE("the new keys refuse bad values with one line", "[schemes][adaptive][cli]") {
  for (const auto& [args, expected] : std::vector<std::pair<std::string, std::string>>{
           {"solve undamped --set scheme=dopri5 --set rtol=0", "rtol=0 is out of range"},
           {"solve undamped --set scheme=dopri5 --set rtol=-1e-6", "give a relative tolerance in [1e-14, 1)"},
           {"solve undamped --set scheme=dopri5 --set rtol=1e-17", "rtol=1e-17 is out of range"},
           {"solve undamped --set scheme=dopri5 --set rtol=9e-15", "rtol=9e-15 is out of range"},
           {"solve undamped --set scheme=dopri5 --set rtol=2", "rtol=2 is out of range"},
           {"solve undamped --set scheme=rkf45 --set rtol=abc", "cannot read rtol='abc'"},
           {"solve undamped --set scheme=dopri5 --set atol=-1", "atol=-1 is out of range"},
           {"solve undamped --set scheme=dopri5 --set atol=1/0", "atol"},
           {"solve undamped --set scheme=dopri6", "choose one of"},
           {"analyze convergence undamped --set scheme=dopri5", "dopri5 chooses its own"},
           {"analyze empirical undamped --set scheme=rkf45", "rkf45 chooses its own"},
           {"analyze amplitude --schemes rk4,dopri5", "dopri5 chooses its own"},
           {"plot undamped --set scheme=dopri5 --set rtol=0 -o OUT.png", "rtol=0 is out of range"},
       })
    vibra::test::check_refused(args, expected);
}

TEST_CASE("with --allow-unstable, solve, plot, render and ascii draw the growth above the stability limit (Fig 1.5)", "[schemes][cli]") {
  // dt = 0.3184 is just above 1/pi for w = 2 pi: refused, then run with a warning.
  const std::string run = "undamped --set dt=0.3184 --set T=20";
  vibra::test::check_refused("solve " + run, "or draw the growth with --allow-unstable");
  const auto r = run_vibra("solve " + run + " --allow-unstable");
  REQUIRE(r.exit_code == 0);
  CHECK(r.err == "vibra: warning: dt=0.3184 is above the stability limit 0.31831 of scheme centered for this "
                 "problem: the solution will grow (--allow-unstable)\n");
  const auto table = vibra::test::csv_rows(r.out);
  CHECK(std::abs(std::stod(table.back()[1])) > 2);  // it grows
  vibra::test::ScratchDirectory dir;
  for (const std::string command : {"plot " + run + " -q -o " + (dir / "u.png"),
                                    "render " + run + " --at 10 -q --size 320x180 -o " + (dir / "s.png"),
                                    "ascii " + run + " --width 40"}) {
    INFO(command);
    const auto other = run_vibra(command + " --allow-unstable");
    CHECK(other.exit_code == 0);
    CHECK_THAT(other.err, Catch::Contains("vibra: warning: dt=0.3184"));
  }
}

TEST_CASE("Exercise 1.4: centered against dopri5 at rtol 1e-14", "[schemes][adaptive][cli]") {
  vibra::test::ScratchDirectory dir;
  const auto r = run_vibra("plot undamped --compare scheme=centered,dopri5 --set rtol=1e-14 -q -o " + (dir / "e.png"));
  INFO(r.err);
  CHECK(r.exit_code == 0);
  CHECK(std::filesystem::file_size(dir.path / "e.png") > 1000);
}
