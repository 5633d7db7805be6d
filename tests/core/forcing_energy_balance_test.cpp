// Each forced model's forcing against its formula, and its energy balance:
// the work of the forcing = the change of energy + what damping dissipates.
#include <catch2/catch.hpp>

#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "core/models/model.hpp"
#include "test_support.hpp"

using namespace vibra;

namespace {
/// One forced model: its settings, its forcing written out from the book's
/// equation (force times velocity, as a function of the row {t, u, v, ...}),
/// and the power its damping takes.
struct ForcedModel {
  std::string name;
  std::vector<std::string> settings;
  std::function<double(double t)> force;       ///< F(t), in the energy's units per unit velocity
  std::function<double(double v)> dissipated;  ///< the damping's power, b v^2
  double force_tolerance;  ///< relative; the road's h'' comes from heights every wavelength/100 (O(dx^2))
};

const double kPi = M_PI;

/// Policy as a table: the models with a forcing term, each written from its equation.
std::vector<ForcedModel> forced_models() {
  // vibration (1.71): m u'' + b u' + k u = F(t), E = m v^2/2 + k u^2/2.
  // rlc: L q'' + R q' + q/C = V(t), E = L I^2/2 + q^2/(2C).
  // resonance: u'' + beta u' + u = sin(gamma t), E per unit mass.
  // bumpy road (section 1.12.8): m u'' + b u' + k u = -m h''(s t) s^2 with
  // h = A sin(2 pi x / wavelength), so -m h'' s^2 = m A (2 pi/wavelength)^2 s^2 sin(2 pi s t/wavelength).
  const double A = 0.05, wavelength = 2, speed = 10, mass = 60, K = 2 * kPi / wavelength;
  return {
      {"vibration", {"m=2", "k=3", "b=0.3", "F=0.5*sin(2*t)", "I=1", "V=0"},
       [](double t) { return 0.5 * std::sin(2 * t); }, [](double v) { return 0.3 * v * v; }, 1e-12},
      {"rlc", {"L=0.5", "R=0.2", "C=0.25", "V=sin(3*t)", "q0=0.1", "I0=0"},
       [](double t) { return std::sin(3 * t); }, [](double v) { return 0.2 * v * v; }, 1e-12},
      {"resonance", {"beta=0.1", "gamma=1.3", "I=0.2", "V=0"},
       [](double t) { return std::sin(1.3 * t); }, [](double v) { return 0.1 * v * v; }, 1e-12},
      {"bumpy-road", {"m=60", "k=60000", "b=600", "speed=10", "road=sine", "A=0.05", "wavelength=2"},
       [=](double t) { return mass * A * K * K * speed * speed * std::sin(K * speed * t); },
       [](double v) { return 600 * v * v; }, 2e-3},
  };
}

/// What a run of the model shows against the formulas: the worst relative
/// error of its forcing power, and its energy balance's mismatch relative to
/// the energy that flowed (trapezoidal sums over the rows).
struct Balance {
  double worst_force_error = 0, mismatch = 0, flowed = 0;
};

Balance balance_of(const ForcedModel& f, int steps_per_period) {
  std::vector<std::string> settings = f.settings;
  settings.insert(settings.end(), {"scheme=rk4", "periods=4", "steps_per_period=" + std::to_string(steps_per_period)});
  auto run = test::trajectory(f.name, settings);
  REQUIRE(run->info().forcing_power);
  Balance b;
  double largest_power = 0;
  std::vector<double> row(run->width()), previous;
  run->row(row);
  const double E0 = run->info().energy(row).total();
  double work = 0, dissipated = 0, moved = 0;
  auto power = [&](const std::vector<double>& r) { return run->info().forcing_power(r); };
  do {
    run->row(row);
    const double expected = f.force(row[0]) * row[2];
    largest_power = std::max(largest_power, std::abs(expected));
    b.worst_force_error = std::max(b.worst_force_error, std::abs(power(row) - expected));
    if (!previous.empty()) {
      const double dt = row[0] - previous[0];
      work += 0.5 * dt * (power(row) + power(previous));
      dissipated += 0.5 * dt * (f.dissipated(row[2]) + f.dissipated(previous[2]));
      moved += 0.5 * dt * (std::abs(power(row)) + std::abs(power(previous)) + f.dissipated(row[2]) + f.dissipated(previous[2]));
    }
    previous = row;
  } while (run->advance());
  b.worst_force_error /= largest_power;
  b.mismatch = std::abs(run->info().energy(row).total() - E0 - (work - dissipated));
  b.flowed = moved;
  return b;
}
}  // namespace

TEST_CASE("each forced model's forcing power is its formula F(t) v", "[models][forcing]") {
  for (const ForcedModel& f : forced_models()) {
    INFO(f.name << ": forcing power against F(t) v from the model's equation");
    CHECK(balance_of(f, 100).worst_force_error < f.force_tolerance);
  }
}

TEST_CASE("each forced model's work of the forcing is its change of energy plus its dissipation", "[models][forcing]") {
  // The trapezoidal sums err by O(dt^2): halving dt quarters the mismatch,
  // which stays a small part of the energy that flowed.
  for (const ForcedModel& f : forced_models()) {
    const Balance coarse = balance_of(f, 200), fine = balance_of(f, 400);
    INFO(f.name << ": E(T) - E(0) vs work - dissipation, mismatch " << coarse.mismatch << " then " << fine.mismatch
                << " of " << coarse.flowed << " that flowed");
    CHECK(coarse.mismatch < 1e-4 * coarse.flowed);
    CHECK(fine.mismatch < 0.35 * coarse.mismatch);
  }
}
