#include <cmath>

#include "core/error.hpp"
#include "core/models/model.hpp"
#include "core/models/vibration_law.hpp"

namespace vibra {

// m u'' + f(u') + s(u) = F(t) (1.71): a linear spring k u, or s and F typed as formulas.
ModelDefinition vibration_model() {
  ModelDefinition m;
  m.name = "vibration";
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
    if ((info.exact = free_linear_solution(law, I, V))) info.exact_label = "exact";
    auto system = law.system();
    return std::make_unique<SecondOrderTrajectory<1>>(
        system, Vec<1>(I), Vec<1>(V), info, [](const Sample<1>& x, std::span<double> out) {
          out[0] = x.t, out[1] = x.u[0], out[2] = x.v[0];
        });
  };
  return m;
}

}  // namespace vibra
