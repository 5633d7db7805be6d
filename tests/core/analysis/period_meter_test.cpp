// Periods between upward zero crossings, located by cubic Hermite
// interpolation, and the logarithmic decrement of damped runs.
#include <catch2/catch.hpp>

#include <cmath>

#include "core/analysis/frequency/pendulum_period.hpp"
#include "core/analysis/frequency/period_meter.hpp"
#include "test_support.hpp"

using namespace vibra;

namespace {
/// The largest |P_i - exact| over a run.
double worst_period_error(const std::string& scheme, int steps_per_period, double exact) {
  auto t = test::trajectory("pendulum", {"alpha=0", "Theta=60", "scheme=" + scheme,
                                         "steps_per_period=" + std::to_string(steps_per_period), "periods=8"});
  const auto periods = measure_periods(*t);
  REQUIRE(periods.size() >= 5);
  double worst = 0;
  for (const auto& p : periods) worst = std::max(worst, std::abs(p.period - exact));
  return worst;
}
}  // namespace

TEST_CASE("a sampled cosine's crossings are found to the interpolation's order", "[period]") {
  // u = cos(t - 1) sampled with its derivative: crossings at 1 + 3 pi/2 + 2 pi k.
  for (double h : {0.2, 0.1}) {
    PeriodMeter meter;
    for (int n = 0; n * h <= 20; ++n) meter.add(n * h, std::cos(n * h - 1), -std::sin(n * h - 1));
    REQUIRE(meter.crossings().size() == 3);
    for (size_t k = 0; k < 3; ++k) CHECK(meter.crossings()[k] == Approx(1 + 1.5 * M_PI + 2 * M_PI * k).margin(h * h * h * h * 0.05));
    // One maximum (u = 1) between successive crossings and one after the last.
    const auto peaks = meter.peaks();
    REQUIRE(peaks.size() == 3);
    for (double a : peaks) CHECK(a == Approx(1).margin(h * h * h * h * 0.05));
  }
}

TEST_CASE("a sample exactly at zero is a crossing, counted once, at its own time", "[period]") {
  // u = cos t sampled at quarter periods: u is exactly -1, 0, 1, 0, -1, ...,
  // so each upward crossing (t = 3 pi/2 + 2 pi k) falls on a sample.
  PeriodMeter meter;
  const double u[] = {1, 0, -1, 0}, v[] = {0, -1, 0, 1};
  for (int n = 0; n <= 16; ++n) meter.add(n * M_PI / 2, u[n % 4], v[n % 4]);
  REQUIRE(meter.crossings().size() == 4);
  for (size_t k = 0; k < 4; ++k) CHECK(meter.crossings()[k] == Approx(1.5 * M_PI + 2 * M_PI * k).epsilon(1e-12));
}

TEST_CASE("undamped periods equal 2 pi / w", "[period]") {
  auto t = test::trajectory("undamped", {"scheme=rk4", "w=3", "steps_per_period=200", "periods=6", "I=0.3", "V=2"});
  CHECK(t->info().exact_period == Approx(2 * M_PI / 3).epsilon(1e-15));
  const auto periods = measure_periods(*t);
  // Upward crossings at 0.93, 1.93, ... 5.93 periods: five periods, the last
  // without a following maximum (it would come at 6.18).
  REQUIRE(periods.size() == 5);
  for (const auto& p : periods) CHECK(p.period == Approx(2 * M_PI / 3).epsilon(1e-7));  // RK4's phase error ~1e-8
  for (size_t i = 0; i < 4; ++i) CHECK(std::abs(periods[i].log_decrement) < 1e-8);  // no damping: equal maxima
  CHECK(std::isnan(periods[4].log_decrement));
}

TEST_CASE("measured pendulum periods converge to 4 K(sin(Theta/2)) at the scheme's order", "[period]") {
  const double exact = pendulum_period(M_PI / 3);
  CHECK(test::trajectory("pendulum", {"alpha=0", "Theta=60"})->info().exact_period == Approx(exact).epsilon(1e-15));
  for (auto [scheme, order] : {std::pair{"rk4", 4}, std::pair{"centered", 2}}) {
    const double coarse = worst_period_error(scheme, 40, exact), fine = worst_period_error(scheme, 80, exact),
                 finer = worst_period_error(scheme, 160, exact);
    INFO(scheme << ": errors " << coarse << ", " << fine << ", " << finer);
    CHECK(std::log2(coarse / fine) == Approx(order).margin(0.2));
    CHECK(std::log2(fine / finer) == Approx(order).margin(0.2));
  }
  // And the true period is not the small-angle one: 7.3% longer.
  CHECK(worst_period_error("rk4", 160, 2 * M_PI) > 0.45);
}

TEST_CASE("the logarithmic decrement of linear damping is zeta w P_d", "[period]") {
  // m u'' + b u' + k u = 0: u = A exp(-zeta w t) cos(w_d t + phi), whose
  // maxima are P_d = 2 pi / w_d apart, so ln(a_i/a_{i+1}) = zeta w P_d exactly.
  const double m = 2, k = 5, b = 0.6, w = std::sqrt(k / m), zeta = b / (2 * m * w);
  const double w_d = w * std::sqrt(1 - zeta * zeta), P_d = 2 * M_PI / w_d;
  auto t = test::trajectory("vibration", {"m=2", "s=5*u", "b=0.6", "scheme=rk4", "steps_per_period=400", "periods=6"});
  REQUIRE(t->info().damped);
  const auto periods = measure_periods(*t);
  REQUIRE(periods.size() >= 4);
  for (size_t i = 0; i + 1 < periods.size(); ++i) {
    CHECK(periods[i].period == Approx(P_d).epsilon(1e-9));
    CHECK(periods[i].log_decrement == Approx(zeta * w * P_d).epsilon(1e-8));
  }
}

TEST_CASE("an eccentric orbit's x repeats with Kepler's period 2 pi a^(3/2)", "[period]") {
  // x0 = 1, v0 = 1.2: E = 0.72 - 1 = -0.28, a = -1/(2E) = 1.7857.
  auto t = test::trajectory("two-body", {"vy0=1.2", "scheme=pefrl", "steps_per_period=2000", "periods=4"});
  const double kepler = 2 * M_PI * std::pow(1 / 0.56, 1.5);
  CHECK(t->info().exact_period == Approx(kepler).epsilon(1e-14));
  const auto periods = measure_periods(*t);
  REQUIRE(periods.size() == 3);
  for (const auto& p : periods) CHECK(p.period == Approx(kepler).epsilon(1e-6));
}

TEST_CASE("a run without a full period measures nothing", "[period]") {
  auto t = test::trajectory("undamped", {"periods=0.9"});
  CHECK(measure_periods(*t).empty());
}
