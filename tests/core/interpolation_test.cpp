// The Hermite interpolant an adaptive run without dense output of its own
// (rkf45) and an impact's location use between steps: u by quintic Hermite
// through u, v and the acceleration at both ends, v by cubic Hermite through
// v and the acceleration. Held here against exact solutions: the interpolant
// alone (exact samples) converges at 6th order in u and 4th in v. A
// fixed-step run is drawn between its steps as straight lines instead
// (discrete_curve_test.cpp).
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "core/math/hermite.hpp"
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
