// Frames between solver steps: u is interpolated by quintic Hermite through
// u, v and the acceleration at both ends, v by cubic Hermite through v and
// the acceleration. Held here against exact solutions: the interpolant alone
// (exact samples) converges at 6th order in u and 4th in v, and a trajectory's rows between steps agree with the exact
// solution to its scheme's accuracy, for u and for v.
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "core/hermite.hpp"
#include "test_support.hpp"

namespace {

/// Largest error of the interpolant between exact samples of u = cos t
/// (v = -sin t, u'' = -cos t), over one period at 7 points per step.
std::pair<double, double> interpolant_error(double h) {
  double eu = 0, ev = 0;
  for (double a = 0; a < 2 * M_PI; a += h) {
    const double b = a + h;
    const vibra::Sample<1> sa{a, vibra::Vec<1>(std::cos(a)), vibra::Vec<1>(-std::sin(a))};
    const vibra::Sample<1> sb{b, vibra::Vec<1>(std::cos(b)), vibra::Vec<1>(-std::sin(b))};
    for (int k = 1; k < 8; ++k) {
      const double t = a + h * k / 8;
      const auto s = vibra::hermite_between<1>(sa, vibra::Vec<1>(-std::cos(a)), sb, vibra::Vec<1>(-std::cos(b)), t);
      eu = std::max(eu, std::abs(s.u[0] - std::cos(t)));
      ev = std::max(ev, std::abs(s.v[0] + std::sin(t)));
    }
  }
  return {eu, ev};
}

}  // namespace

TEST_CASE("interpolation between steps converges at 6th order in u and 4th in v", "[interpolation]") {
  const auto [u1, v1] = interpolant_error(0.2);
  const auto [u2, v2] = interpolant_error(0.1);
  INFO("u: " << u1 << " -> " << u2 << ", v: " << v1 << " -> " << v2);
  CHECK(std::log2(u1 / u2) == Approx(6).margin(0.3));
  CHECK(std::log2(v1 / v2) == Approx(4).margin(0.3));
  // Exact for a quintic: free fall between impacts (u = -t^2/2) to rounding.
  const vibra::Sample<1> a{0, vibra::Vec<1>(1.0), vibra::Vec<1>(0.0)}, b{1, vibra::Vec<1>(0.5), vibra::Vec<1>(-1.0)};
  const auto mid = vibra::hermite_between<1>(a, vibra::Vec<1>(-1.0), b, vibra::Vec<1>(-1.0), 0.3);
  CHECK(mid.u[0] == Approx(1 - 0.045).epsilon(1e-14));
  CHECK(mid.v[0] == Approx(-0.3).epsilon(1e-14));
}

TEST_CASE("rows between steps follow the exact solution in u and v at the scheme's order", "[interpolation]") {
  // RK4 on u'' + u = 0: between steps the error is the scheme's (4th order),
  // not the interpolant's; a wrong end's acceleration would make it 2nd.
  auto error_between = [](int steps_per_period) {
    auto run = vibra::test::trajectory(
        "undamped", {"scheme=rk4", "steps_per_period=" + std::to_string(steps_per_period), "periods=2"});
    const auto& exact = run->info().exact;
    std::vector<double> row(run->width());
    double eu = 0, ev = 0;
    while (run->advance()) {
      const double b = run->t(), a = b - run->info().mesh.dt;
      for (double f : {0.25, 0.5, 0.8}) {
        const double t = a + f * (b - a);
        run->row_at(t, row);
        eu = std::max(eu, std::abs(row[1] - exact(t)));
        const double h = 1e-6;  // the exact velocity by a central difference of the exact u
        ev = std::max(ev, std::abs(row[2] - (exact(t + h) - exact(t - h)) / (2 * h)));
      }
    }
    return std::pair{eu, ev};
  };
  const auto [u1, v1] = error_between(20);
  const auto [u2, v2] = error_between(40);
  INFO("u: " << u1 << " -> " << u2 << ", v: " << v1 << " -> " << v2);
  CHECK(std::log2(u1 / u2) == Approx(4).margin(0.4));
  CHECK(std::log2(v1 / v2) == Approx(4).margin(0.4));
}
