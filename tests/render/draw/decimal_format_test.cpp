// Tests of one-decimal formatting: the same text as printf("%.1f"), ties and signs included.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>

#include "render/draw/decimal_format.hpp"

using vibra::render::format_one_decimal;

namespace {
std::string ours(double x) {
  char buf[400];
  return std::string(buf, format_one_decimal(buf, x));
}
std::string printfs(double x) {
  char buf[400];
  return std::string(buf, std::snprintf(buf, sizeof buf, "%.1f", x));
}
}  // namespace

TEST_CASE("one-decimal formatting matches printf, ties and signs included", "[ascii]") {
  for (double x : {0.0, -0.0, 0.05, 0.15, 0.25, -0.25, 0.04, -0.04, 0.95, 9.95, 99.95, 1e14 + 0.25, 2.5, -2.5, 1e16, -1e300,
                   double(INFINITY), -double(INFINITY), double(NAN)})
    CHECK(ours(x) == printfs(x));
  // The counter's usual values: t/P on a mesh of 60 steps per period, where
  // every sixth value is near a tie, and random values.
  for (int n = 0; n < 200000; ++n) {
    const double x = (n * (2 * M_PI / 60)) / (2 * M_PI);
    if (ours(x) != printfs(x)) FAIL("n = " << n << ": " << ours(x) << " vs " << printfs(x));
  }
  std::mt19937_64 random(42);
  std::uniform_real_distribution<double> uniform(-1e4, 1e4);
  for (int n = 0; n < 200000; ++n) {
    const double x = uniform(random);
    if (ours(x) != printfs(x)) FAIL(x << ": " << ours(x) << " vs " << printfs(x));
  }
}
