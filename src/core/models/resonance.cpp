// The resonance model u'' + beta u' + u = sin(gamma t) (Exercise 1.22), with its exact solution.
#include <cmath>

#include "core/error.hpp"
#include "core/models/model.hpp"

namespace vibra {

namespace {
/// u(t) of u'' + beta u' + u = sin(gamma t), u(0) = I, u'(0) = V: the steady
/// response plus the free decay that meets the initial conditions
/// (docs/models.md). Empty for beta >= 2 (no oscillating decay).
std::function<double(double)> exact_response(double beta, double gamma, double I, double V) {
  if (beta >= 2) return {};
  // Particular solution u_p and its value and slope at t = 0.
  std::function<double(double)> particular;
  double p0 = 0, p1 = 0;
  if (beta == 0 && gamma == 1) {
    particular = [](double t) { return -0.5 * t * std::cos(t); };  // undamped resonance grows linearly
    p0 = 0, p1 = -0.5;
  } else {
    const double A = steady_amplitude(beta, gamma), phi = std::atan2(beta * gamma, 1 - gamma * gamma);
    particular = [=](double t) { return A * std::sin(gamma * t - phi); };
    p0 = -A * std::sin(phi), p1 = A * gamma * std::cos(phi);
  }
  const double zeta = beta / 2, wd = std::sqrt(1 - zeta * zeta), c1 = I - p0, c2 = V - p1;
  return [=](double t) {
    return particular(t) + std::exp(-zeta * t) * (c1 * std::cos(wd * t) + (c2 + zeta * c1) / wd * std::sin(wd * t));
  };
}
}  // namespace

double steady_amplitude(double beta, double gamma) {
  return 1 / std::sqrt((1 - gamma * gamma) * (1 - gamma * gamma) + (beta * gamma) * (beta * gamma));
}

// Forced vibration scaled by the natural frequency and the static deflection
// (section 1.12.4, Exercise 1.22): u'' + beta u' + u = sin(gamma t).
ModelDefinition resonance_model() {
  ModelDefinition m;
  m.name = "resonance";
  m.equation = R"(u'' + \beta u' + u = \sin(\gamma t))";
  m.equation_for = [](const Parameters& p) -> std::string {
    return p.number("beta") == 0 ? R"(u'' + u = \sin(\gamma t))" : R"(u'' + \beta u' + u = \sin(\gamma t))";
  };
  m.summary = "u'' + beta u' + u = sin(gamma t), forced vibration scaled (section 1.12.4; the washing machine)";
  m.keys = {
      {"beta", ValueKind::number, "0.05", "", "damping b/(m w), 2 zeta", {}, {}},
      {"gamma", ValueKind::number, "1.1", "", "forcing frequency over the natural frequency", {}, {}},
      {"I", ValueKind::number, "0", "static deflections", "initial displacement u(0)", {}, {}},
      {"V", ValueKind::number, "0", "", "initial velocity u'(0)", {}, {}},
  };
  m.columns = {"t", "u", "v"};
  m.time_defaults = {"centered", "60", "30"};
  m.build = [columns = m.columns, name = m.name](const Parameters& p) -> std::unique_ptr<Trajectory> {
    const double beta = p.number("beta"), gamma = p.number("gamma"), I = p.number("I"), V = p.number("V");
    if (!(beta >= 0) || std::isinf(beta)) throw UsageError("beta=" + p.text("beta") + " must be >= 0");
    if (!(gamma >= 0) || std::isinf(gamma)) throw UsageError("gamma=" + p.text("gamma") + " must be >= 0");
    TrajectoryInfo info;
    info.columns = columns;
    info.mesh = resolve_time_mesh(p, 2 * M_PI, std::max(1.0, gamma));
    reject_adjusted_scheme(info.mesh, name);
    if ((info.exact = exact_response(beta, gamma, I, V))) info.exact_label = "exact";
    info.damped = beta > 0;
    // Energy per unit mass in units of k times the static deflection squared;
    // the forcing's work makes it change even without damping.
    info.energy = [](std::span<const double> row) { return EnergyParts{0.5 * row[2] * row[2], 0.5 * row[1] * row[1]}; };
    info.energy_unit = "k (static deflection)^2";
    info.forcing_power = [gamma](std::span<const double> row) { return std::sin(gamma * row[0]) * row[2]; };
    auto system = std::make_shared<SecondOrderSystem<1>>(SecondOrderSystem<1>::general(
        [gamma](const Vec<1>& u, double t) { return Vec<1>(std::sin(gamma * t) - u[0]); }));
    system->damping = beta > 0 ? Damping::linear : Damping::none;
    system->damping_per_mass = beta;
    return std::make_unique<SecondOrderTrajectory<1>>(
        system, Vec<1>(I), Vec<1>(V), info, [](const Sample<1>& x, std::span<double> out) {
          out[0] = x.t, out[1] = x.u[0], out[2] = x.v[0];
        });
  };
  return m;
}

}  // namespace vibra
