// The two-body model: a light planet around a heavy star, scaled: x'' = -x / |x|^3 (Exercise 1.28).
#include <cmath>

#include "core/error.hpp"
#include "core/models/model.hpp"

namespace vibra {

ModelDefinition two_body_model() {
  ModelDefinition m;
  m.name = "two-body";
  m.equation = R"(\mathbf{x}'' = -\frac{\mathbf{x}}{|\mathbf{x}|^3})";
  m.summary = "planet around a heavy star, scaled x'' = -x/|x|^3 (Exercise 1.28); default: circular orbit";
  m.keys = {
      {"x0", ValueKind::number, "1", "", "initial x", {}, {}},
      {"y0", ValueKind::number, "0", "", "initial y", {}, {}},
      {"vx0", ValueKind::number, "0", "", "initial x velocity", {}, {}},
      {"vy0", ValueKind::number, "1", "", "initial y velocity", {}, {}},
  };
  m.columns = {"t", "x", "y", "vx", "vy"};
  m.time_defaults = {"pefrl", "200", "10"};
  m.build = [columns = m.columns, name = m.name](const Parameters& p) -> std::unique_ptr<Trajectory> {
    const Vec<2> u0(p.number("x0"), p.number("y0")), v0(p.number("vx0"), p.number("vy0"));
    const double r0 = u0.norm();
    if (r0 == 0) throw UsageError("the planet cannot start at the star: give x0 or y0 != 0");
    // Kepler: semi-major axis from the energy; bound orbits have a period.
    const double energy = 0.5 * v0.squaredNorm() - 1 / r0;
    const double a = energy < 0 ? -0.5 / energy : 0;
    TrajectoryInfo info;
    info.columns = columns;
    info.mesh = resolve_time_mesh(p, a > 0 ? 2 * M_PI * std::pow(a, 1.5) : 0, 0);
    reject_adjusted_scheme(info.mesh, name);
    const bool circular = std::abs(u0.dot(v0)) < 1e-14 && std::abs(v0.squaredNorm() * r0 - 1) < 1e-14;
    if (circular) {
      const double w = std::pow(r0, -1.5), phase = std::atan2(u0[1], u0[0]);
      const double sense = u0[0] * v0[1] - u0[1] * v0[0] > 0 ? 1 : -1;
      info.exact = [=](double t) { return r0 * std::cos(phase + sense * w * t); };
      info.exact_label = "exact";
    }
    info.amplitude_bound = a > 0 ? 2 * a : 0;
    // x crosses zero upward once per orbit around the star at the origin.
    info.exact_period = info.mesh.period;
    info.exact_period_label = "Kepler's 2π<i>a</i><sup>3/2</sup>";
    info.energy = [](std::span<const double> row) {
      return EnergyParts{0.5 * (row[3] * row[3] + row[4] * row[4]), -1 / std::hypot(row[1], row[2])};
    };
    info.energy_unit = "per unit mass, scaled";
    auto system = std::make_shared<SecondOrderSystem<2>>(SecondOrderSystem<2>::general([](const Vec<2>& x, double) -> Vec<2> {
      const double r2 = x.squaredNorm();
      return -x / (r2 * std::sqrt(r2));
    }));
    return std::make_unique<SecondOrderTrajectory<2>>(
        system, u0, v0, info, [](const Sample<2>& s, std::span<double> out) {
          out[0] = s.t, out[1] = s.u[0], out[2] = s.u[1], out[3] = s.v[0], out[4] = s.v[1];
        });
  };
  return m;
}

}  // namespace vibra
