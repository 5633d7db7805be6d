// The centered scheme's numerical frequency (1.18), its series (1.19), and
// `vibra analyze frequency`'s table.
#include <catch2/catch.hpp>
#include <cmath>
#include <sstream>

#include "cli_support.hpp"
#include "core/analysis/frequency/numerical_frequency.hpp"
#include "core/error.hpp"

using namespace vibra;

TEST_CASE("the numerical frequency matches (1.18), (1.19) and the stability limit", "[analysis]") {
  const double w = 2 * M_PI;
  CHECK(numerical_frequency(w, 0.1) == Approx(20 * std::asin(M_PI / 10)).epsilon(1e-15));
  CHECK(numerical_frequency(w, 1 / M_PI) == Approx(M_PI * M_PI).epsilon(1e-12));  // at the limit, pi / dt
  CHECK(numerical_frequency_series(w, 0.1) == Approx(w * (1 + w * w * 0.01 / 24)).epsilon(1e-15));
  // The series is off by O(dt^4): the difference falls 16x per halving.
  const double e1 = numerical_frequency(w, 0.02) - numerical_frequency_series(w, 0.02);
  const double e2 = numerical_frequency(w, 0.01) - numerical_frequency_series(w, 0.01);
  CHECK(e1 / e2 == Approx(16).epsilon(0.01));
  CHECK_THROWS_WITH(numerical_frequency(w, 0.32), Catch::Contains("stability limit"));
}

TEST_CASE("vibra analyze frequency prints (1.18) and (1.19) for each steps per period", "[analysis]") {
  const auto r = test::run_vibra("analyze frequency --w 2 --steps-per-period 40,10,4 --csv");
  REQUIRE(r.exit_code == 0);
  std::istringstream out(r.out);
  std::string line;
  std::getline(out, line);
  CHECK(line == "dt,steps_per_period,w_tilde,w_series,w_tilde_rel_error,w_series_rel_error");
  const double w = 2;
  std::vector<double> steps;
  while (std::getline(out, line)) {
    INFO(line);
    std::istringstream cells(line);
    std::vector<double> v;
    for (std::string cell; std::getline(cells, cell, ',');) v.push_back(std::stod(cell));
    REQUIRE(v.size() == 6);
    CHECK(v[0] == Approx(2 * M_PI / (w * v[1])).epsilon(1e-14));
    CHECK(v[2] == Approx(2 / v[0] * std::asin(w * v[0] / 2)).epsilon(1e-14));
    CHECK(v[3] == Approx(w * (1 + w * w * v[0] * v[0] / 24)).epsilon(1e-14));
    CHECK(v[4] == Approx(v[2] / w - 1).epsilon(1e-12));
    steps.push_back(v[1]);
  }
  // The last row is the stability limit dt = 2/w, N_P = pi.
  CHECK(steps == std::vector<double>{40, 10, 4, M_PI});
}
