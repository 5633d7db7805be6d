// Every closed-form solution a model offers, checked against the mathematics alone: it satisfies
// its ODE and initial conditions; and every energy bound on the swing is the one the energy gives.
#include <catch2/catch.hpp>
#include <cmath>
#include <functional>

#include "test_support.hpp"

using vibra::test::rows;
using vibra::test::trajectory;

namespace {
/// An ODE as its residual r(t, u, u', u'') = 0, with its initial values.
struct ExactCase {
  const char* model;
  std::vector<std::string> settings;
  double I, V;
  std::function<double(double t, double u, double up, double upp)> residual;
};
}  // namespace

TEST_CASE("every exact solution satisfies its ODE and its initial values, masses other than 1 included", "[models]") {
  // Residuals by central differences of the exact u: a wrong factor (a mass
  // left out, a sign, a phase) leaves a residual of the force's size.
  const std::vector<ExactCase> cases = {
      {"undamped", {"w=3", "I=0.5", "V=1"}, 0.5, 1, [](double, double u, double, double upp) { return upp + 9 * u; }},
      {"vibration", {"m=2", "k=8", "b=1.2", "I=0.5", "V=1"}, 0.5, 1,  // zeta = 0.15
       [](double, double u, double up, double upp) { return 2 * upp + 1.2 * up + 8 * u; }},
      {"vibration", {"m=2", "k=8", "F=3*sin(1.5*t)", "I=0.5", "V=1"}, 0.5, 1,
       [](double t, double u, double, double upp) { return 2 * upp + 8 * u - 3 * std::sin(1.5 * t); }},
      {"vibration", {"m=2", "k=8", "F=3*sin(2*t)", "I=0.5", "V=1"}, 0.5, 1,  // at resonance: w = sqrt(8/2) = 2
       [](double t, double u, double, double upp) { return 2 * upp + 8 * u - 3 * std::sin(2 * t); }},
      {"resonance", {"beta=0.3", "gamma=1.7", "I=0.4", "V=-0.2"}, 0.4, -0.2,
       [](double t, double u, double up, double upp) { return upp + 0.3 * up + u - std::sin(1.7 * t); }},
      {"resonance", {"beta=0", "gamma=1", "I=0.4", "V=-0.2"}, 0.4, -0.2,
       [](double t, double u, double, double upp) { return upp + u - std::sin(t); }},
      // gamma = 0: the drum stands still, sin(0 t) = 0, the free damped machine.
      {"resonance", {"beta=0.3", "gamma=0", "I=0.4", "V=-0.2"}, 0.4, -0.2,
       [](double, double u, double up, double upp) { return upp + 0.3 * up + u; }},
      {"rlc", {"L=2", "R=0.5", "C=0.25", "q0=1", "I0=0.3"}, 1, 0.3,
       [](double, double q, double qp, double qpp) { return 2 * qpp + 0.5 * qp + q / 0.25; }},
  };
  const double h = 1e-4;
  for (const ExactCase& c : cases) {
    INFO(c.model << " " << c.settings[0] << " " << c.settings[1] << " " << c.settings[2]);
    const auto run = trajectory(c.model, c.settings);
    const auto u = run->info().exact;
    REQUIRE(u);
    CHECK(u(0) == Approx(c.I).margin(1e-12));
    CHECK((u(h) - u(-h)) / (2 * h) == Approx(c.V).margin(1e-6));
    for (double t : {0.3, 1.1, 2.7, 5.0, 9.4}) {
      INFO("t = " << t);
      const double up = (u(t + h) - u(t - h)) / (2 * h), upp = (u(t + h) - 2 * u(t) + u(t - h)) / (h * h);
      CHECK(std::abs(c.residual(t, u(t), up, upp)) < 1e-5);
    }
  }
}

TEST_CASE("an undamped, unforced run swings exactly as far as its energy allows, soft springs too", "[models]") {
  // Bound u_max from P(u_max) = E(0), found here by bisection on each
  // model's own potential; the fine run reaches it and never passes it.
  struct BoundCase {
    const char* model;
    std::vector<std::string> settings;
    std::function<double(double)> potential;  ///< per the kinetic energy's mass
    double E0;
  };
  const auto log_cosh = [](double a) { return [a](double u) { return std::log(std::cosh(a * u)) / (a * a); }; };
  const std::vector<BoundCase> cases = {
      {"vibration", {"m=2", "k=8", "I=0.5", "V=1"}, [](double u) { return 4 * u * u; }, 4 * 0.25 + 1},
      {"rlc", {"L=2", "R=0", "C=0.25", "q0=1", "I0=0.6"}, [](double q) { return 2 * q * q; }, 2 + 0.36},
      {"sliding-box", {"mu=0", "alpha=2", "I=1", "V=1"}, log_cosh(2), log_cosh(2)(1) + 0.5},
      {"sliding-box", {"mu=0.05", "alpha=1.5", "I=1", "V=0"}, log_cosh(1.5), log_cosh(1.5)(1)},
  };
  for (const BoundCase& c : cases) {
    INFO(c.model << " " << c.settings[0] << " " << c.settings[1]);
    double lo = 0, hi = 100;
    for (int i = 0; i < 200; ++i) (c.potential(0.5 * (lo + hi)) < c.E0 ? lo : hi) = 0.5 * (lo + hi);
    auto settings = c.settings;
    settings.insert(settings.end(), {"scheme=rk4", "steps_per_period=400", "periods=2"});
    auto run = trajectory(c.model, settings);
    CHECK(run->info().amplitude_bound == Approx(lo).epsilon(1e-9));
    double largest = 0;
    for (const auto& row : rows(*run)) largest = std::max(largest, std::abs(row[1]));
    CHECK(largest <= lo * (1 + 1e-6));
    // Friction takes energy out: the bound is then not reached.
    if (c.settings[0] == std::string("mu=0") || c.model != std::string("sliding-box")) CHECK(largest == Approx(lo).epsilon(1e-4));
  }
}
