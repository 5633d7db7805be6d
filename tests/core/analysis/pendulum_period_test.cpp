// The pendulum's true period 4 K(sin(Theta/2)) by the arithmetic-geometric mean.
#include <catch2/catch.hpp>

#include <cmath>

#include "core/analysis/frequency/pendulum_period.hpp"
#include "core/math/quadrature.hpp"

using namespace vibra;

TEST_CASE("K(k) matches tabulated values to 1e-12", "[period]") {
  // Abramowitz & Stegun, Table 17.1, K as a function of m = k^2.
  const std::pair<double, double> table[] = {
      {0.0, M_PI / 2},           {0.25, 1.6857503548125960}, {0.5, 1.8540746773013719},
      {0.75, 2.1565156474996432}, {0.9, 2.5780921133481732},  {0.99, 3.6956373629898747},
  };
  for (auto [m, K] : table) {
    INFO("m = " << m);
    CHECK(complete_elliptic_k(std::sqrt(m)) == Approx(K).epsilon(1e-12));
    CHECK(complete_elliptic_k_complementary(std::sqrt(1 - m)) == Approx(K).epsilon(1e-12));
  }
  CHECK(std::isinf(complete_elliptic_k(1)));
}

TEST_CASE("K(k) agrees with its defining integral", "[period]") {
  for (double k : {0.1, 0.5, 0.8, 0.95}) {
    const double integral = integrate([k](double phi) { return 1 / std::sqrt(1 - k * k * std::pow(std::sin(phi), 2)); }, 0,
                                      M_PI / 2);
    CHECK(complete_elliptic_k(k) == Approx(integral).epsilon(1e-13));
  }
}

TEST_CASE("the pendulum at 60 degrees needs 6.743 time units, not 2 pi", "[period]") {
  CHECK(pendulum_period(M_PI / 3) == Approx(6.7430014192503842).epsilon(1e-13));
  CHECK(pendulum_period(0) == Approx(2 * M_PI).epsilon(1e-15));
  CHECK(pendulum_period(1e-4) == Approx(2 * M_PI * (1 + 1e-8 / 16)).epsilon(1e-14));  // P = 2 pi (1 + Theta^2/16 + ...)
  CHECK(std::isinf(pendulum_period(M_PI)));
}

TEST_CASE("near the top K follows ln(4/k') where 1 - k^2 would have lost every digit", "[period]") {
  // K = ln(4/k') + O(k'^2 ln k') as k' -> 0.
  CHECK(complete_elliptic_k_complementary(1e-9) == Approx(std::log(4e9)).epsilon(1e-14));
  // Released 1e-6 rad below the top, the pendulum takes 4 ln(8/1e-6) (up to the rounding of pi - 1e-6).
  CHECK(pendulum_period(M_PI - 1e-6) == Approx(4 * std::log(8e6)).epsilon(1e-9));
}
