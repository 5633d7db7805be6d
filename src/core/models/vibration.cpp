// The vibration model (1.71): m u'' + f(u') + s(u) = F(t) with formula forces typed by the user.
#include <algorithm>
#include <cmath>
#include <functional>

#include "core/error.hpp"
#include "core/models/model.hpp"
#include "core/models/potential_reach.hpp"
#include "core/models/vibration_law.hpp"
#include "core/math/quadrature.hpp"

namespace vibra {

// m u'' + f(u') + s(u) = F(t) (1.71): a linear spring k u, or s and F typed as formulas.
ModelDefinition vibration_model() {
  ModelDefinition m;
  m.name = "vibration";
  m.equation = R"(m u'' + f(u') + s(u) = F(t))";
  // The damping and spring chosen, written out: b u' or b|u'|u', k u or s(u), F(t) or 0.
  m.equation_for = [](const Parameters& p) {
    const std::string damping = p.choice("damping");
    std::string f = p.number("b") == 0 || damping == "none" ? "" : damping == "linear" ? R"( + b u')" : R"( + b|u'|u')";
    const std::string s = p.given("s") ? " + s(u)" : " + k u";
    const bool forced = p.has_value("F") && VibrationLaw::unless_zero(p.formula("F"));
    return R"(m u'')" + f + s + (forced ? " = F(t)" : " = 0");
  };
  m.summary = "m u'' + f(u') + s(u) = F(t), the generalized model (1.71)";
  m.keys = {
      {"m", ValueKind::number, "1", "mass", "mass", {}, {}},
      {"k", ValueKind::number, "1", "force/length", "spring stiffness: s(u) = k u unless s is given", {}, {}},
      {"b", ValueKind::number, "0", "mass/time or mass/length", "damping coefficient", {}, {}},
      {"damping", ValueKind::choice, "linear", "", "damping law f(u'): b u' (linear) or b |u'| u' (quadratic)",
       {"none", "linear", "quadratic"}, {}},
      {"s", ValueKind::formula, "", "force", "restoring force s(u), a formula in u (instead of k)", {}, {"u"}},
      {"F", ValueKind::formula, "0", "force", "external force F(t), a formula in t", {}, {"t"}},
      {"I", ValueKind::number, "1", "length", "initial displacement u(0)", {}, {}},
      {"V", ValueKind::number, "0", "length/time", "initial velocity u'(0)", {}, {}},
  };
  m.columns = {"t", "u", "v"};
  m.time_defaults = {"centered", "40", "10"};
  m.build = [columns = m.columns, name = m.name](const Parameters& p) -> std::unique_ptr<Trajectory> {
    const VibrationLaw law = VibrationLaw::from(p);
    const double I = p.number("I"), V = p.number("V");
    // Small oscillations about u = 0 have w^2 = s'(0)/m.
    const double stiffness = law.small_oscillation_stiffness();
    const double w = stiffness > 0 && std::isfinite(stiffness) ? std::sqrt(stiffness / law.mass) : 0;

    TrajectoryInfo info;
    info.columns = columns;
    info.mesh = resolve_time_mesh(p, w > 0 ? 2 * M_PI / w : 0, w);
    reject_adjusted_scheme(info.mesh, name);
    if (!(info.exact = free_linear_solution(law, I, V))) info.exact = sine_forced_solution(law, I, V);
    if (info.exact) info.exact_label = "exact";
    auto system = law.system();
    info.damped = law.damping != Damping::none;
    // 0.5 m v^2 + P(u), P(u) = integral_0^u s: exact for the linear spring,
    // by quadrature for any formula s (exact in one pass for a polynomial).
    const auto potential = [law](double u) {
      return law.linear_spring() ? 0.5 * law.k * u * u : integrate([&law](double x) { return law.spring(x); }, 0, u);
    };
    info.energy = [potential, mass = law.mass](std::span<const double> row) {
      return EnergyParts{0.5 * mass * row[2] * row[2], potential(row[1])};
    };
    info.energy_unit = "mass length^2/time^2";
    if (law.F) info.forcing_power = [law](std::span<const double> row) { return law.external(row[0]) * row[2]; };
    // Without forcing the energy never grows, so it bounds the amplitude.
    if (!law.F) {
      const double E0 = 0.5 * law.mass * V * V + potential(I);
      const double step = std::max({std::abs(I), w > 0 ? std::abs(V) / w : std::abs(V), 1e-3}) / 8;
      if (E0 > 0) info.amplitude_bound = potential_reach(potential, I, E0, step);
    }
    return std::make_unique<SecondOrderTrajectory<1>>(
        system, Vec<1>(I), Vec<1>(V), info, [](const Sample<1>& x, std::span<double> out) {
          out[0] = x.t, out[1] = x.u[0], out[2] = x.v[0];
        });
  };
  return m;
}

}  // namespace vibra
