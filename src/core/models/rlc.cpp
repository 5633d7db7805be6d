// The rlc model, the series RLC circuit (section 1.12.11): solved for the charge, L q'' + R q' + q/C = V(t), I = q'.
// L I'' + R I' + I/C = V'(t) is solved for the charge so that V itself is
// needed and not its derivative. It is the generalized model (1.71) with
// m = L, linear damping b = R, spring k = 1/C and force F = V.
#include <cmath>

#include "core/error.hpp"
#include "core/models/model.hpp"
#include "core/models/vibration_law.hpp"

namespace vibra {

ModelDefinition rlc_model() {
  ModelDefinition m;
  m.name = "rlc";
  m.equation = R"(L q'' + R q' + \frac{q}{C} = V(t),\quad I = q')";
  m.equation_for = [](const Parameters& p) -> std::string {
    const bool driven = p.has_value("V") && VibrationLaw::unless_zero(p.formula("V"));
    return std::string(p.number("R") == 0 ? R"(L q'' + \frac{q}{C})" : R"(L q'' + R q' + \frac{q}{C})") +
           (driven ? " = V(t)" : " = 0") + R"(,\quad I = q')";
  };
  m.time_unit = "s";
  m.summary = "series RLC circuit L q'' + R q' + q/C = V(t), I = q' (section 1.12.11)";
  m.keys = {
      {"L", ValueKind::number, "1", "H", "inductance L > 0", {}, {}},
      {"R", ValueKind::number, "0.2", "ohm", "resistance R >= 0", {}, {}},
      {"C", ValueKind::number, "1", "F", "capacitance C > 0", {}, {}},
      {"V", ValueKind::formula, "0", "V", "source voltage V(t), a formula in t", {}, {"t"}},
      {"q0", ValueKind::number, "1", "C", "initial charge q(0) on the capacitor", {}, {}},
      {"I0", ValueKind::number, "0", "A", "initial current I(0)", {}, {}},
  };
  m.columns = {"t", "q", "I", "V"};
  m.time_defaults = {"centered", "60", "10"};
  m.build = [columns = m.columns, name = m.name](const Parameters& p) -> std::unique_ptr<Trajectory> {
    VibrationLaw law;
    law.mass = p.positive("L");
    law.k = 1 / p.positive("C");
    law.b = p.number("R");
    if (!(law.b >= 0) || !std::isfinite(law.b)) throw UsageError("R=" + p.text("R") + " must be a finite resistance >= 0");
    if (!std::isfinite(law.mass) || !std::isfinite(law.k) || law.k == 0)
      throw UsageError("L and C must be finite and > 0, e.g. L=1 C=0.25");
    law.damping = law.b > 0 ? Damping::linear : Damping::none;
    law.F = VibrationLaw::unless_zero(p.formula("V"));
    const double q0 = p.number("q0"), I0 = p.number("I0");
    if (!std::isfinite(q0) || !std::isfinite(I0)) throw UsageError("q0 and I0 must be finite numbers");
    const double w = std::sqrt(law.k / law.mass);  // 1/sqrt(LC)

    TrajectoryInfo info;
    info.columns = columns;
    info.mesh = resolve_time_mesh(p, 2 * M_PI / w, w);
    reject_adjusted_scheme(info.mesh, name);
    if ((info.exact = free_linear_solution(law, q0, I0))) info.exact_label = "exact";
    // Without a source the energy L I^2/2 + q^2/(2C) only falls.
    info.damped = law.b > 0;
    // Energy in the inductor's field and the capacitor's: 0.5 L I^2 + q^2/(2C).
    info.energy = [L = law.mass, inverse_C = law.k](std::span<const double> row) {
      return EnergyParts{0.5 * L * row[2] * row[2], 0.5 * inverse_C * row[1] * row[1]};
    };
    info.energy_unit = "J";
    if (law.F) info.forcing_power = [law](std::span<const double> row) { return law.external(row[0]) * row[2]; };
    if (!law.F) info.amplitude_bound = std::sqrt(q0 * q0 + I0 * I0 / (w * w));
    return std::make_unique<SecondOrderTrajectory<1>>(law.system(), Vec<1>(q0), Vec<1>(I0), info,
                                                      [law](const Sample<1>& x, std::span<double> out) {
                                                        out[0] = x.t, out[1] = x.u[0], out[2] = x.v[0];
                                                        out[3] = law.external(x.t);
                                                      });
  };
  return m;
}

}  // namespace vibra
