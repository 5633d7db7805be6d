// Adaptive Gauss-Kronrod quadrature: the potentials of formula restoring forces.
#include <catch2/catch.hpp>

#include <cmath>

#include "core/math/quadrature.hpp"

using namespace vibra;

TEST_CASE("Gauss-Kronrod integrates polynomials exactly and smooth functions to rounding", "[quadrature]") {
  int calls = 0;
  const double cubic = integrate([&](double x) { ++calls; return 4 * x * x * x - x; }, 0, 2);
  CHECK(cubic == Approx(14).epsilon(1e-15));
  CHECK(calls == 15);  // one pass of the 15-point rule
  CHECK(integrate([](double x) { return std::exp(x); }, 0, 3) == Approx(std::exp(3) - 1).epsilon(1e-14));
  CHECK(integrate([](double x) { return std::sin(x); }, 0, 1.3) == Approx(1 - std::cos(1.3)).epsilon(1e-14));
  // Reversed limits give minus the integral; equal limits nothing.
  CHECK(integrate([](double x) { return std::exp(x); }, 1, 0) == Approx(1 - std::exp(1)).epsilon(1e-14));
  CHECK(integrate([](double) { return 1.0; }, 2, 2) == 0);
}

TEST_CASE("a kink costs bounded work and still a close answer", "[quadrature]") {
  int calls = 0;
  const double value = integrate([&](double x) { ++calls; return std::abs(x - 0.3); }, -1, 2);
  CHECK(value == Approx(0.5 * 1.3 * 1.3 + 0.5 * 1.7 * 1.7).epsilon(1e-10));
  CHECK(calls < 15 * 500);
}
