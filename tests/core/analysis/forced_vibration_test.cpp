// The spring-mass systems of Figs 1.17, 1.18 and the resonance model
// (section 1.12.4) against their exact solutions, at their schemes' orders.
#include <catch2/catch.hpp>
#include <cmath>

#include "core/analysis/resonance.hpp"
#include "core/error.hpp"
#include "test_support.hpp"

using namespace vibra;
using vibra::test::rows;
using vibra::test::str;
using vibra::test::trajectory;

namespace {
/// Discrete L2 error of u against the model's exact solution.
double l2_error(const std::string& model, std::vector<std::string> settings) {
  auto run = trajectory(model, settings);
  const auto exact = run->info().exact;
  REQUIRE(exact);
  const double dt = run->info().mesh.dt;
  double sum = 0;
  for (const auto& row : rows(*run)) sum += std::pow(row[1] - exact(row[0]), 2);
  return std::sqrt(dt * sum);
}

double rate(const std::string& model, const std::vector<std::string>& settings, double steps) {
  auto with = [&](double n) {
    auto s = settings;
    s.push_back("steps_per_period=" + str(n));
    return l2_error(model, s);
  };
  return std::log2(with(steps) / with(2 * steps));
}
}  // namespace

TEST_CASE("spring (Fig 1.17): u = I cos(wt) + V/w sin(wt), rates of the schemes", "[models][vibration]") {
  const std::vector<std::string> spring = {"m=2", "k=8", "I=0.5", "V=1", "periods=4"};
  CHECK(rate("vibration", {"m=2", "k=8", "I=0.5", "V=1", "periods=4", "scheme=centered"}, 40) == Approx(2).margin(0.1));
  CHECK(rate("vibration", {"m=2", "k=8", "I=0.5", "V=1", "periods=4", "scheme=rk4"}, 20) == Approx(4).margin(0.15));
  CHECK(rate("vibration", {"m=2", "k=8", "I=0.5", "V=1", "periods=4", "scheme=euler-cromer"}, 200) == Approx(1).margin(0.1));
  CHECK(l2_error("vibration", {"m=2", "k=8", "I=0.5", "V=1", "periods=4", "steps_per_period=400"}) < 1e-3);
}

TEST_CASE("spring and dashpot (Fig 1.18): the damped exact solution, rates of the schemes", "[models][vibration]") {
  // zeta = b / (2 sqrt(k m)) = 0.25.
  const std::vector<std::string> damped = {"m=1", "k=4", "b=1", "I=1", "V=0.5", "periods=3"};
  for (auto [scheme, order, steps] : {std::tuple{"centered", 2, 40}, {"rk4", 4, 20}, {"crank-nicolson", 2, 40},
                                      std::tuple{"staggered", 2, 40}}) {
    auto s = damped;
    s.push_back(std::string("scheme=") + scheme);
    INFO(scheme);
    CHECK(rate("vibration", s, steps) == Approx(order).margin(0.15));
  }
  // Quadratic damping and forcing have no exact solution here.
  CHECK_FALSE(trajectory("vibration", {"b=1", "damping=quadratic"})->info().exact);
  CHECK_FALSE(trajectory("vibration", {"F=cos(t)"})->info().exact);
  CHECK_THROWS_WITH(trajectory("vibration", {"k=2", "s=u"}), Catch::Contains("either k"));
}

TEST_CASE("resonance model: the exact forced response, at the schemes' orders", "[models][resonance]") {
  for (const char* gamma : {"0.5", "1.1", "3"}) {
    INFO("gamma " << gamma);
    const std::vector<std::string> forced = {"beta=0.2", std::string("gamma=") + gamma, "I=0.3", "V=-0.2", "periods=3"};
    auto s = forced;
    s.push_back("scheme=centered");
    CHECK(rate("resonance", s, 60) == Approx(2).margin(0.1));
    s.back() = "scheme=rk4";
    CHECK(rate("resonance", s, 30) == Approx(4).margin(0.15));
  }
  // Undamped resonance grows as -t cos(t)/2.
  CHECK(l2_error("resonance", {"beta=0", "gamma=1", "periods=5", "scheme=rk4", "steps_per_period=200"}) < 1e-5);
  // The free decay oscillates below beta = 2 only: just under it the exact
  // response holds, at critical damping (its 1/sqrt(1 - beta^2/4) would be
  // 1/0) and above it there is none, rather than a column of NaN.
  CHECK(l2_error("resonance", {"beta=1.99", "gamma=0.7", "I=0.3", "periods=3", "scheme=rk4", "steps_per_period=200"}) < 1e-7);
  CHECK_FALSE(trajectory("resonance", {"beta=2"})->info().exact);
  CHECK_FALSE(trajectory("resonance", {"beta=3"})->info().exact);
}

TEST_CASE("resonance: measured steady amplitudes within 1% of 1/sqrt((1-g^2)^2 + (b g)^2) (Exercise 1.22)",
          "[analysis][resonance]") {
  for (double beta : {0.005, 0.05, 0.2})
    for (double gamma : {5.0, 1.5, 1.1, 1.0}) {
      const ResonancePoint p = measure_steady_amplitude(beta, gamma);
      INFO("beta " << beta << ", gamma " << gamma);
      CHECK(p.amplitude == Approx(p.exact).epsilon(0.01));
      if (gamma == 1) CHECK(p.exact == Approx(1 / beta));
    }
  CHECK_THROWS_AS(measure_steady_amplitude(0, 1), UsageError);
}
