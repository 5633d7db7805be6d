#include <algorithm>
#include <cmath>
#include <functional>

#include "core/error.hpp"
#include "core/models/model.hpp"
#include "core/quadrature.hpp"

namespace vibra {

namespace {
/// How far u can go from u0 with energy E0 = potential(u0) + kinetic: the
/// largest |u| at which `potential` first reaches E0, searched outward from
/// u0 on both sides (doubling the step, then bisecting). 0 when it does not
/// reach E0 within 1e6 steps' worth (a force that does not restore).
double reach(const std::function<double(double)>& potential, double u0, double E0, double step) {
  double largest = 0;
  for (double side : {1.0, -1.0}) {
    double below = 0, above = step;
    while (potential(u0 + side * above) < E0) {
      below = above, above *= 2;
      if (above > 1e6 * step) return 0;
    }
    for (int i = 0; i < 60; ++i) {
      const double mid = 0.5 * (below + above);
      (potential(u0 + side * mid) < E0 ? below : above) = mid;
    }
    largest = std::max(largest, std::abs(u0 + side * above));
  }
  return largest;
}

bool is_zero_constant(const std::string& formula) {
  try {
    return evaluate_constant("F", formula) == 0;
  } catch (const UsageError&) {
    return false;  // depends on t
  }
}
}  // namespace

// m u'' + f(u') + s(u) = F(t) (1.71), with s and F typed as formulas.
ModelDefinition vibration_model() {
  ModelDefinition m;
  m.name = "vibration";
  m.summary = "m u'' + f(u') + s(u) = F(t), the generalized model (1.71)";
  m.keys = {
      {"m", ValueKind::number, "1", "mass", "mass", {}, {}},
      {"b", ValueKind::number, "0", "mass/time or mass/length", "damping coefficient", {}, {}},
      {"damping", ValueKind::choice, "linear", "", "damping law f(u'): b u' (linear) or b |u'| u' (quadratic)",
       {"none", "linear", "quadratic"}, {}},
      {"s", ValueKind::formula, "u", "force", "restoring force s(u), a formula in u", {}, {"u"}},
      {"F", ValueKind::formula, "0", "force", "external force F(t), a formula in t", {}, {"t"}},
      {"I", ValueKind::number, "1", "length", "initial displacement u(0)", {}, {}},
      {"V", ValueKind::number, "0", "length/time", "initial velocity u'(0)", {}, {}},
  };
  m.columns = {"t", "u", "v"};
  m.time_defaults = {"centered", "40", "10"};
  m.build = [columns = m.columns, name = m.name](const Parameters& p) -> std::unique_ptr<Trajectory> {
    const double mass = p.positive("m"), b = p.number("b"), I = p.number("I"), V = p.number("V");
    if (b < 0) throw UsageError("b=" + p.text("b") + " must be >= 0 (negative damping feeds energy in)");
    const Expression s = p.formula("s"), F = p.formula("F");
    // Small oscillations about u = 0 have w^2 = s'(0)/m.
    const double h = 1e-6, stiffness = (s(h) - s(-h)) / (2 * h);
    const double w = stiffness > 0 && std::isfinite(stiffness) ? std::sqrt(stiffness / mass) : 0;

    TrajectoryInfo info;
    info.columns = columns;
    info.mesh = resolve_time_mesh(p, w > 0 ? 2 * M_PI / w : 0, w);
    reject_adjusted_scheme(info.mesh, name);
    auto system = std::make_shared<SecondOrderSystem<1>>(SecondOrderSystem<1>::general(
        [s, F, mass](const Vec<1>& u, double t) -> Vec<1> { return Vec<1>((F(t) - s(u[0])) / mass); }));
    const std::string law = p.choice("damping");
    system->damping = b == 0 || law == "none" ? Damping::none : law == "linear" ? Damping::linear : Damping::quadratic;
    info.damped = system->damping != Damping::none;
    // 0.5 m v^2 + P(u), P(u) = integral_0^u s: the potential of any formula s,
    // by quadrature (exact in one pass for a polynomial s such as k u).
    info.energy = [s, mass](std::span<const double> row) {
      return EnergyParts{0.5 * mass * row[2] * row[2], integrate([&s](double x) { return s(x); }, 0, row[1])};
    };
    info.energy_unit = "mass length^2/time^2";
    // Without forcing the energy never grows, so it bounds the amplitude.
    if (is_zero_constant(p.text("F"))) {
      const auto potential = [&s](double u) { return integrate([&s](double x) { return s(x); }, 0, u); };
      const double E0 = 0.5 * mass * V * V + potential(I);
      const double step = std::max({std::abs(I), w > 0 ? std::abs(V) / w : std::abs(V), 1e-3}) / 8;
      if (E0 > 0) info.amplitude_bound = reach(potential, I, E0, step);
    }
    system->damping_per_mass = b / mass;
    return std::make_unique<SecondOrderTrajectory<1>>(
        system, Vec<1>(I), Vec<1>(V), info, [](const Sample<1>& x, std::span<double> out) {
          out[0] = x.t, out[1] = x.u[0], out[2] = x.v[0];
        });
  };
  return m;
}

}  // namespace vibra
