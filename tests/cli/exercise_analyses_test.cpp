// The analyses the chapter's exercises ask for, through the real command:
// fd-accuracy (Exercise 1.8), convergence of several schemes in one figure
// (Fig 1.1), the energy error's rate (1.9), the phase lag (1.2), the forced
// spring's exact solution (1.12) and the error panel; and their bad input.
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>

#include "cli_support.hpp"

using vibra::test::check_refused;
using vibra::test::csv_rows;
using vibra::test::run_vibra;
using vibra::test::ScratchDirectory;

TEST_CASE("analyze fd-accuracy: E(p) = 4 sin^2(p/2)/p^2 and its Taylor polynomial on [0, pi]", "[analysis][cli]") {
  const auto r = run_vibra("analyze fd-accuracy --points 5 --csv");
  REQUIRE(r.exit_code == 0);
  const auto rows = csv_rows(r.out);
  REQUIRE(rows.size() == 6);
  CHECK(rows[0] == std::vector<std::string>{"p", "E", "taylor"});
  for (size_t i = 1; i < rows.size(); ++i) {
    const double p = std::stod(rows[i][0]), E = std::stod(rows[i][1]), taylor = std::stod(rows[i][2]);
    CHECK(p == Approx(M_PI * (i - 1) / 4));
    const double expected = p == 0 ? 1 : 4 * std::pow(std::sin(p / 2), 2) / (p * p);
    CHECK(E == Approx(expected).epsilon(1e-15));
    CHECK(taylor == Approx(1 - p * p / 12 + std::pow(p, 4) / 360).epsilon(1e-15));
  }
  CHECK(std::stod(rows.back()[1]) == Approx(4 / (M_PI * M_PI)).epsilon(1e-15));  // E(pi) = 4/pi^2
  ScratchDirectory dir;
  CHECK(run_vibra("analyze fd-accuracy -q -o " + (dir / "e.png")).exit_code == 0);
  CHECK(std::filesystem::file_size(dir.path / "e.png") > 1000);
}

TEST_CASE("analyze convergence --compare: a study per scheme, each at its rate, one figure", "[analysis][cli]") {
  ScratchDirectory dir;
  const auto r = run_vibra("analyze convergence undamped --compare scheme=centered,centered-adjusted,rk3 --levels 5 "
                           "--csv -q -o " + (dir / "f.png"));
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  const auto rows = csv_rows(r.out);
  REQUIRE(rows.size() == 16);
  CHECK(rows[0] == std::vector<std::string>{"scheme", "i", "dt", "E", "r"});
  CHECK(rows[5][0] == "centered");
  CHECK(std::stod(rows[5][4]) == Approx(2).margin(0.05));
  CHECK(rows[10][0] == "centered-adjusted");
  CHECK(std::stod(rows[10][4]) == Approx(4).margin(0.05));
  CHECK(rows[15][0] == "rk3");
  CHECK(std::stod(rows[15][4]) == Approx(3).margin(0.1));
  CHECK(std::filesystem::file_size(dir.path / "f.png") > 1000);
  // The table's title names the schemes as read, whatever the spacing typed.
  const auto titled = run_vibra("analyze convergence undamped --compare 'scheme=centered, rk4' --levels 3");
  REQUIRE(titled.exit_code == 0);
  CHECK(titled.out.rfind("Convergence of undamped, schemes centered,rk4: ", 0) == 0);
}

TEST_CASE("analyze energy --rates: the energy error's convergence rate (Exercise 1.9)", "[analysis][cli]") {
  const auto r = run_vibra("analyze energy --schemes euler-cromer,crank-nicolson --T 10 --dt 0.05,0.025,0.0125 --rates --csv");
  REQUIRE(r.exit_code == 0);
  const auto rows = csv_rows(r.out);
  REQUIRE(rows.size() == 7);
  CHECK(rows[0].back() == "rate");
  for (size_t i : {1, 4}) CHECK(rows[i][4].empty());  // a group's first row has no rate
  for (size_t i : {2, 3, 5, 6}) CHECK(std::stod(rows[i][4]) == Approx(2).margin(0.1));
  // Without --rates the table is the book's.
  CHECK(csv_rows(run_vibra("analyze energy --csv").out)[0].size() == 4);
}

TEST_CASE("analyze empirical's phase_lag grows linearly with the periods (Exercise 1.2)", "[analysis][cli]") {
  const auto r = run_vibra("analyze empirical undamped --set steps_per_period=20 --set periods=20 --csv");
  REQUIRE(r.exit_code == 0);
  const auto rows = csv_rows(r.out);
  REQUIRE(rows.size() > 15);
  CHECK(rows[0].back() == "phase_lag");
  // The centered scheme's w~ = (2/dt) asin(w dt/2) runs ahead by 2 pi (1 - w/w~) a period.
  const double w = 2 * M_PI, dt = 1.0 / 20, w_tilde = 2 / dt * std::asin(w * dt / 2);
  for (size_t k = 1; k < rows.size(); ++k) {
    const double i = std::stod(rows[k][1]) + 1;  // maxima after the one at t = 0
    CHECK(std::stod(rows[k][6]) == Approx(-2 * M_PI * i * (1 - w / w_tilde)).epsilon(1e-6));
  }
  // No exact solution, no phase lag: the column is empty.
  const auto pendulum = csv_rows(run_vibra("analyze empirical pendulum --set alpha=0.2 --csv").out);
  REQUIRE(pendulum.size() > 1);
  CHECK(pendulum[1][6].empty());
}

TEST_CASE("the forced undamped spring A sin(phi t) converges at rate 2 to its exact solution (Exercise 1.12)",
          "[analysis][cli]") {
  for (const char* force : {"F=sin(3*t)", "F=2*sin(2*t)", "F=0.5*sin(pi*t)"}) {  // 2*sin(2*t): resonance, w = 2
    INFO(force);
    const auto r = run_vibra(std::string("analyze convergence vibration --set k=4 --set \"") + force + "\" --levels 4 --csv");
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    CHECK(std::stod(csv_rows(r.out).back()[3]) == Approx(2).margin(0.02));
  }
  // Not a sine of t alone, or with damping: no exact solution.
  check_refused("analyze convergence vibration --set k=4 --set \"F=sin(3*t)+1\"", "no exact solution");
  check_refused("analyze convergence vibration --set k=4 --set b=0.1 --set \"F=sin(3*t)\"", "no exact solution");
}

TEST_CASE("plot --panels error draws u - u_exact, and needs an exact solution", "[analysis][cli]") {
  ScratchDirectory dir;
  const auto r = run_vibra("plot undamped --panels u,error --set periods=4 -q -o " + (dir / "e.png"));
  INFO(r.err);
  CHECK(r.exit_code == 0);
  CHECK(run_vibra("plot undamped --panels error --set periods=4 -q -o " + (dir / "e.html")).exit_code == 0);
  check_refused("plot pendulum --panels theta,error -o OUT.png", "panel 'error' needs an exact solution");
  check_refused("plot vibration --set \"F=cos(t)\" --panels error -o OUT.png", "panel 'error' needs an exact solution");
}

TEST_CASE("the new analysis options refuse bad input with one line", "[analysis][cli]") {
  check_refused("analyze fd-accuracy --points 1", "--points must be 2..100000");
  check_refused("analyze convergence undamped --compare dt=0.1,0.05", "compares schemes only");
  check_refused("analyze convergence undamped --compare scheme=rk4", "needs 2 to 8 schemes");
  check_refused("analyze convergence undamped --compare scheme=rk4,rk7", "'rk7' is not a valid scheme");
  check_refused("analyze energy --schemes rk4,dopri5 --rates", "dopri5 chooses its own");
}
