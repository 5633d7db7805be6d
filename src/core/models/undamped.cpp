// The undamped model: u'' + w^2 u = 0, u(0) = I, u'(0) = V (section 1.1); the scaled model has w = 2 pi, so the period is 1.
#include <cmath>

#include "core/error.hpp"
#include "core/models/model.hpp"

namespace vibra {

ModelDefinition undamped_model() {
  ModelDefinition m;
  m.name = "undamped";
  m.equation = R"(u'' + \omega^2 u = 0)";
  m.summary = "u'' + w^2 u = 0, the undamped oscillator of section 1.1";
  m.keys = {
      {"I", ValueKind::number, "1", "length", "initial displacement u(0)", {}, {}},
      {"V", ValueKind::number, "0", "length/time", "initial velocity u'(0)", {}, {}},
      {"w", ValueKind::number, "2*pi", "1/time", "angular frequency", {}, {}},
  };
  m.columns = {"t", "u", "v"};
  m.time_defaults = {"centered", "40", "10"};
  m.build = [columns = m.columns](const Parameters& p) -> std::unique_ptr<Trajectory> {
    const double I = p.number("I"), V = p.number("V"), w = p.positive("w");
    TrajectoryInfo info;
    info.columns = columns;
    info.mesh = resolve_time_mesh(p, 2 * M_PI / w, w);
    info.amplitude_bound = std::hypot(I, V / w);
    info.exact = [=](double t) { return I * std::cos(w * t) + V / w * std::sin(w * t); };
    info.exact_label = "exact";
    info.exact_period = 2 * M_PI / w;
    info.exact_period_label = "2π/<i>ω</i>";
    info.energy = [w](std::span<const double> row) {
      return EnergyParts{0.5 * row[2] * row[2], 0.5 * w * w * row[1] * row[1]};
    };
    info.energy_unit = "per unit mass";
    double w_scheme = w;
    if (info.mesh.scheme == Scheme::centered_adjusted) w_scheme = w * (1 - w * w * info.mesh.dt * info.mesh.dt / 24);
    auto system = std::make_shared<SecondOrderSystem<1>>(SecondOrderSystem<1>::spring(w_scheme * w_scheme));
    return std::make_unique<SecondOrderTrajectory<1>>(
        system, Vec<1>(I), Vec<1>(V), info, [](const Sample<1>& s, std::span<double> out) {
          out[0] = s.t, out[1] = s.u[0], out[2] = s.v[0];
        });
  };
  return m;
}

/// Models other than `undamped` reject the adjusted-frequency scheme.
void reject_adjusted_scheme(const TimeMesh& mesh, const std::string& model) {
  if (mesh.scheme == Scheme::centered_adjusted)
    throw UsageError("scheme centered-adjusted applies to model undamped only, not " + model +
                     ": choose centered or another scheme");
}

}  // namespace vibra
