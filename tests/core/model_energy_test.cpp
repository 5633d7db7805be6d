// Every model's kinetic and potential energy (TrajectoryInfo::energy), with
// the scheme's own velocity, verified against what the mathematics promises.
#include <catch2/catch.hpp>

#include <cmath>

#include "core/models/model.hpp"
#include "test_support.hpp"

using namespace vibra;

namespace {
double energy(const Trajectory& t) {
  std::vector<double> row(t.width());
  t.row(row);
  return t.info().energy(row).total();
}

/// max_n |E^n - E^0| / |E^0| over a run.
double max_energy_drift(Trajectory& t) {
  const double E0 = energy(t);
  double worst = 0;
  while (t.advance()) worst = std::max(worst, std::abs(energy(t) - E0) / std::abs(E0));
  return worst;
}
}  // namespace

TEST_CASE("every model defines its energy", "[model-energy]") {
  for (const auto& model : all_models()) {
    INFO(model.name);
    auto t = test::trajectory(model.name, {});
    CHECK(t->info().energy);
    CHECK_FALSE(t->info().energy_unit.empty());
    CHECK(std::isfinite(energy(*t)));
  }
}

TEST_CASE("Forward Euler multiplies the undamped energy by exactly 1 + w^2 dt^2 per step", "[model-energy]") {
  // u+ = u + dt v, v+ = v - dt w^2 u: 0.5 v+^2 + 0.5 w^2 u+^2 = (1 + w^2 dt^2) E.
  for (double dt : {0.01, 0.05, 0.1}) {
    auto t = test::trajectory("undamped", {"scheme=forward-euler", "dt=" + test::str(dt), "T=5", "I=0.7", "V=1.3"});
    const double w = 2 * M_PI, factor = 1 + w * w * dt * dt;
    double before = energy(*t);
    CHECK(t->info().energy(std::vector<double>{0, 0.7, 1.3}).kinetic == Approx(0.5 * 1.3 * 1.3).epsilon(1e-15));
    CHECK(before == Approx(0.5 * 1.3 * 1.3 + 0.5 * w * w * 0.49).epsilon(1e-15));
    double worst = 0;
    while (t->advance()) {
      const double after = energy(*t);
      worst = std::max(worst, std::abs(after / before / factor - 1));
      before = after;
    }
    INFO("dt = " << dt);
    CHECK(worst < 1e-12);
  }
}

TEST_CASE("the elastic pendulum keeps its energy to the scheme's order without drag", "[model-energy]") {
  // Halving dt divides the energy error by 2^p. RK4's falls by 2^5: near a
  // harmonic motion its amplitude factor is 1 - (w dt)^6/144 per step, so its
  // energy drifts by O(dt^5) over a fixed time, one order better than its phase.
  for (auto [scheme, order] : {std::pair{"rk4", 5}, std::pair{"velocity-verlet", 2}, std::pair{"pefrl", 4}}) {
    double previous = 0;
    for (int n : {40, 80, 160}) {
      auto t = test::trajectory("elastic-pendulum", {std::string("scheme=") + scheme, "steps_per_period=" + std::to_string(n),
                                                     "periods=3", "Theta=40", "eps=0.1", "beta=0.9"});
      const double drift = max_energy_drift(*t);
      if (previous > 0) {
        INFO(scheme << " at " << n << " steps per period: " << previous << " -> " << drift);
        CHECK(std::log2(previous / drift) == Approx(order).margin(0.3));
      }
      previous = drift;
    }
  }
  // Drag takes energy out.
  auto dragged = test::trajectory("elastic-pendulum", {"gamma=0.1", "periods=3"});
  const double E0 = energy(*dragged);
  while (dragged->advance()) {}
  CHECK(energy(*dragged) < E0 - 0.01 * std::abs(E0));
}

TEST_CASE("Backward Euler never raises the energy of the pendulum with drag", "[model-energy]") {
  // Per step dE = -(dw)^2/2 - cos(xi) (dtheta)^2/2 - dt alpha |w| w^2 <= 0 for |theta| < 90 degrees.
  for (const char* Theta : {"10", "70", "85"})
    for (const char* alpha : {"0.05", "0.4", "2"}) {
      auto t = test::trajectory("pendulum", {"scheme=backward-euler", "Theta=" + std::string(Theta),
                                             "alpha=" + std::string(alpha), "steps_per_period=30", "periods=6"});
      double before = energy(*t), worst = -INFINITY;
      while (t->advance()) {
        const double after = energy(*t);
        worst = std::max(worst, after - before);
        before = after;
      }
      INFO("Theta = " << Theta << ", alpha = " << alpha);
      CHECK(worst <= 0);
    }
}

TEST_CASE("the pendulums keep 0.5 omega^2 + 1 - cos(theta) without drag", "[model-energy]") {
  auto simple = test::trajectory("pendulum", {"alpha=0", "Theta=120", "scheme=rk4", "steps_per_period=400"});
  CHECK(energy(*simple) == Approx(1.5).epsilon(1e-15));
  CHECK(max_energy_drift(*simple) < 1e-8);
  auto rod = test::trajectory("physical-pendulum", {"R=0", "Theta=90", "scheme=rk4", "steps_per_period=400"});
  CHECK(rod->info().energy(std::vector<double>{0, 0, 2, 0, 0}).kinetic == Approx(2));
  CHECK(energy(*rod) == Approx(1).epsilon(1e-15));
  CHECK(max_energy_drift(*rod) < 1e-8);
}

TEST_CASE("the potential of a formula s is its integral from 0", "[model-energy]") {
  struct Case {
    const char* s;
    double (*P)(double);
  };
  const Case cases[] = {
      {"4*u", [](double u) { return 2 * u * u; }},
      {"sin(u)", [](double u) { return 2 * std::pow(std::sin(u / 2), 2); }},
      {"2*tanh(3*u)", [](double u) { return 2.0 / 3 * std::log(std::cosh(3 * u)); }},
      {"u + u^3", [](double u) { return 0.5 * u * u + 0.25 * std::pow(u, 4); }},
  };
  for (const Case& c : cases) {
    auto t = test::trajectory("vibration", {std::string("s=") + c.s, "m=2"});
    for (double u : {-2.5, -0.3, 0.01, 0.7, 3.0}) {
      INFO("s = " << c.s << ", u = " << u);
      const EnergyParts e = t->info().energy(std::vector<double>{0, u, 1.5});
      CHECK(e.potential == Approx(c.P(u)).epsilon(1e-12));
      CHECK(e.kinetic == Approx(0.5 * 2 * 1.5 * 1.5));
    }
  }
}

TEST_CASE("with an external force the energy changes by the force's work", "[model-energy]") {
  // m u'' + k u = F0: dE/dt = F0 u', so E(t) - E(0) = F0 (u(t) - u(0)), up to
  // the scheme's error, which falls at RK4's order.
  auto mismatch = [](int steps_per_period) {
    auto t = test::trajectory("vibration", {"F=0.5", "s=3*u", "I=1", "V=0", "scheme=rk4",
                                            "steps_per_period=" + std::to_string(steps_per_period)});
    const double E0 = energy(*t);
    std::vector<double> row(t->width());
    double worst = 0;
    while (t->advance()) {
      t->row(row);
      worst = std::max(worst, std::abs(energy(*t) - E0 - 0.5 * (row[1] - 1)));
    }
    return worst;
  };
  const double coarse = mismatch(100), fine = mismatch(200);
  CHECK(coarse < 1e-6);  // against a work of up to 0.8
  CHECK(std::log2(coarse / fine) > 3.7);
  CHECK(test::trajectory("vibration", {"F=0.5"})->info().damped == false);
  CHECK(test::trajectory("vibration", {"b=0.1"})->info().damped);
}

TEST_CASE("a circular orbit has energy -1/2", "[model-energy]") {
  auto t = test::trajectory("two-body", {"scheme=pefrl", "periods=5"});
  CHECK(energy(*t) == Approx(-0.5).epsilon(1e-15));
  CHECK(max_energy_drift(*t) < 1e-6);
  CHECK(relative_energy_change(-0.4, -0.5) == Approx(0.2));  // gaining energy is positive for E < 0 too
}

TEST_CASE("an unforced vibration's energy bounds its amplitude", "[model-energy]") {
  // P(u_max) = E(0): for s = k u, u_max = sqrt(I^2 + m V^2 / k).
  CHECK(test::trajectory("vibration", {"s=4*u", "m=2", "I=1", "V=3"})->info().amplitude_bound ==
        Approx(std::sqrt(1 + 2 * 9 / 4.0)).epsilon(1e-12));
  CHECK(test::trajectory("vibration", {"s=sin(u)", "I=-1", "b=0.3"})->info().amplitude_bound == Approx(1).epsilon(1e-12));
  // No bound from a force that does not restore, or with forcing.
  CHECK(test::trajectory("vibration", {"s=-u", "V=2", "dt=0.1", "T=1"})->info().amplitude_bound == 0);
  CHECK(test::trajectory("vibration", {"F=cos(t)"})->info().amplitude_bound == 0);
}

TEST_CASE("a pendulum's energy bounds its swing: cos(theta_max) = cos(Theta) - Omega^2/2, and none over the top", "[model-energy]") {
  // Energy: Omega^2/2 + 1 - cos(Theta) = 1 - cos(theta_max) at the turn.
  const double Theta = 30 * M_PI / 180, Omega = 40 * M_PI / 180;
  const double theta_max = std::acos(std::cos(Theta) - 0.5 * Omega * Omega);
  auto t = test::trajectory("pendulum", {"Theta=30", "Omega=40", "alpha=0", "scheme=rk4", "steps_per_period=400", "periods=2"});
  CHECK(t->info().amplitude_bound == Approx(theta_max).epsilon(1e-12));
  // The period 4 K(k), k = sin(theta_max / 2), by Simpson's rule on K's integral.
  const double k = std::sin(theta_max / 2);
  const int n = 2000;
  double K = 0;
  for (int i = 0; i <= n; ++i) {
    const double phi = 0.5 * M_PI * i / n, weight = i == 0 || i == n ? 1 : i % 2 ? 4 : 2;
    K += weight / std::sqrt(1 - k * k * std::sin(phi) * std::sin(phi));
  }
  K *= 0.5 * M_PI / n / 3;
  CHECK(t->info().exact_period == Approx(4 * K).epsilon(1e-9));
  double largest = 0;
  for (const auto& row : test::rows(*t)) largest = std::max(largest, std::abs(row[1]));
  CHECK(largest == Approx(theta_max).epsilon(1e-4));  // the mesh's nearest step to the turn

  // Enough speed to go over the top: no bound, no period, and theta passes 180 degrees.
  auto over = test::trajectory("pendulum", {"Theta=170", "Omega=60", "alpha=0", "periods=2"});
  CHECK(over->info().amplitude_bound == 0);
  CHECK(over->info().exact_period == 0);
  CHECK(test::rows(*over).back()[1] > M_PI);
}

TEST_CASE("a pendulum from physical data has alpha = C_D rho pi R^2 L / (2 m) (1.131)", "[model-energy]") {
  const double L = 2, m = 0.5, R = 0.1, C_D = 0.4, rho = 1.2;
  const double alpha = C_D * rho * M_PI * R * R * L / (2 * m);
  for (const auto& row : test::rows(*test::trajectory("pendulum", {"L=2", "m=0.5", "R=0.1", "Theta=60", "periods=1"})))
    CHECK(row[4] == Approx(-alpha * std::abs(row[2]) * row[2]).margin(1e-17));
}
