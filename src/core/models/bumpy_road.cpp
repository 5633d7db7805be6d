// The bumpy-road model (section 1.12.8): a vehicle on a generated or read road profile.
#include <cmath>
#include <memory>

#include "core/error.hpp"
#include "core/models/model.hpp"
#include "core/input/quoted_value.hpp"
#include "core/models/road_profile.hpp"

namespace vibra {

RoadProfile road_of(const Parameters& p, double length) {
  const std::string road = p.text("road");
  const double A = p.number("A"), wavelength = p.positive("wavelength");
  const double dx = p.given("dx") ? p.positive("dx") : wavelength / 100;
  // The generated road is held as heights every dx: bound their number, so
  // a fast or long drive asks for a clear refusal, not gigabytes.
  constexpr double kMostHeights = 2e7;
  if (road == "sine" || road == "bumps") {
    // A generated road sampled coarser than its shape would miss the bumps;
    // the bound also keeps the number of bumps near the number of heights
    // (dx = 1e9 once meant a loop over 1e9 bumps for 3 heights).
    if (!(dx <= wavelength / 4))
      throw UsageError("dx = " + short_number(dx) + " m is coarser than the road's shape (wavelength/4 = " +
                       short_number(wavelength / 4) + " m): lower dx, or leave it out (wavelength/100)");
    const double heights = length / dx;
    if (!(heights <= kMostHeights))
      throw UsageError("the road of " + short_number(length) + " m (speed " + quoted_value(p.text("speed")) +
                       " m/s over the run) sampled every dx = " + short_number(dx) + " m needs " +
                       short_number(heights) + " heights, more than 2e7: lower speed or T, or raise dx");
  }
  if (road == "sine") return RoadProfile::sine(A, wavelength, length, dx);
  if (road == "bumps") {
    const double seed = p.number("seed");
    if (!(seed >= 0) || seed != std::floor(seed) || seed > 9e15)
      throw UsageError("seed=" + p.text("seed") + " must be a whole number >= 0");
    return RoadProfile::bumps(A, wavelength, length, dx, std::uint64_t(seed));
  }
  if (!p.given("dx")) throw UsageError("road=" + road + " is a file of heights: give their spacing dx (m)");
  return RoadProfile::from_file(road, dx);
}

// A vehicle on a bumpy road (section 1.12.8): m u'' + b u' + k u = -m h''(s t) s^2,
// u the body's displacement from its rest height L over the axle.
ModelDefinition bumpy_road_model() {
  ModelDefinition m;
  m.name = "bumpy-road";
  m.equation = R"(m u'' + b u' + k u = -m h''(s t) s^2)";
  m.time_unit = "s";
  m.summary = "vehicle on a bumpy road, m u'' + b u' + k u = -m h''(s t) s^2 (section 1.12.8), SI units";
  m.keys = {
      {"m", ValueKind::number, "60", "kg", "mass carried by the wheel", {}, {}},
      {"k", ValueKind::number, "60000", "N/m", "spring stiffness", {}, {}},
      {"b", ValueKind::number, "600", "N s/m", "damper coefficient", {}, {}},
      {"speed", ValueKind::number, "10", "m/s", "horizontal speed s", {}, {}},
      {"road", ValueKind::text, "sine", "", "sine, bumps (seeded random), or a file of heights one per line (with dx)", {}, {}},
      {"A", ValueKind::number, "0.05", "m", "road amplitude (sine) or largest bump (bumps)", {}, {}},
      {"wavelength", ValueKind::number, "2", "m", "sine wavelength, or mean bump spacing", {}, {}},
      {"seed", ValueKind::number, "1", "", "random seed of road=bumps", {}, {}},
      {"dx", ValueKind::number, "", "m", "spacing of the heights (file), or of the sampled road (default wavelength/100)", {}, {}},
      {"R", ValueKind::number, "0.3", "m", "wheel radius (drawing)", {}, {}},
      {"L", ValueKind::number, "0.6", "m", "rest height of the body over the axle (drawing)", {}, {}},
      {"I", ValueKind::number, "0", "m", "initial displacement u(0)", {}, {}},
      {"V", ValueKind::number, "0", "m/s", "initial velocity u'(0)", {}, {}},
  };
  m.columns = {"t", "u", "v", "x", "h"};
  m.time_defaults = {"centered", "60", "20"};
  m.build = [columns = m.columns, name = m.name](const Parameters& p) -> std::unique_ptr<Trajectory> {
    const double mass = p.positive("m"), k = p.positive("k"), b = p.number("b"), speed = p.number("speed");
    if (b < 0) throw UsageError("b=" + p.text("b") + " must be >= 0");
    if (!(speed >= 0)) throw UsageError("speed=" + p.text("speed") + " must be >= 0");
    p.positive("R"), p.positive("L");
    const double w = std::sqrt(k / mass);
    TrajectoryInfo info;
    info.columns = columns;
    info.mesh = resolve_time_mesh(p, 2 * M_PI / w, w);
    reject_adjusted_scheme(info.mesh, name);
    if (std::isinf(info.mesh.T)) throw UsageError("a bumpy road is finite: give a finite T or periods");
    const double distance = speed * info.mesh.T;
    // Generated roads run a little past the end, for frames drawn ahead of the vehicle.
    auto road = std::make_shared<RoadProfile>(road_of(p, distance + 2 * p.positive("wavelength")));
    if (road->length() < distance * (1 - 1e-12))
      throw UsageError("the road is " + std::to_string(road->length()) + " m long but the run needs speed*T = " +
                       std::to_string(distance) + " m: shorten T or give a longer road");
    info.damped = b > 0;
    // The body's energy relative to the wheel: the road's push does work on it.
    info.energy = [mass, k](std::span<const double> row) {
      return EnergyParts{0.5 * mass * row[2] * row[2], 0.5 * k * row[1] * row[1]};
    };
    info.energy_unit = "J";
    // The road pushes the body with -m h''(x) speed^2 relative to the wheel.
    info.forcing_power = [road, mass, speed](std::span<const double> row) {
      return -mass * road->curvature(speed * row[0]) * speed * speed * row[2];
    };
    auto system = std::make_shared<SecondOrderSystem<1>>(SecondOrderSystem<1>::general(
        [road, k, mass, speed](const Vec<1>& u, double t) {
          return Vec<1>(-k / mass * u[0] - road->curvature(speed * t) * speed * speed);
        }));
    system->damping = b > 0 ? Damping::linear : Damping::none;
    system->damping_per_mass = b / mass;
    return std::make_unique<SecondOrderTrajectory<1>>(
        system, Vec<1>(p.number("I")), Vec<1>(p.number("V")), info,
        [road, speed](const Sample<1>& x, std::span<double> out) {
          out[0] = x.t, out[1] = x.u[0], out[2] = x.v[0], out[3] = speed * x.t, out[4] = road->height(speed * x.t);
        });
  };
  return m;
}

}  // namespace vibra
