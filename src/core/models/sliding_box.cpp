// The sliding-box model (section 1.12.3, Exercise 1.23): a spring and Coulomb friction, stops at rest.
#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "core/event_trajectory.hpp"
#include "core/models/model.hpp"
#include "core/models/potential_reach.hpp"
#include "core/models/sliding_box_law.hpp"

namespace vibra {

namespace {
double sign(double x) { return x > 0 ? 1 : x < 0 ? -1 : 0; }

/// The linear spring released from rest: each half swing lasts pi and is a
/// half cosine about +mu or -mu, so |u| shrinks by 2 mu per half swing; the
/// box stops at the first turning point with |u| <= mu (docs/models.md).
std::function<double(double)> released_from_rest(double I, double mu) {
  return [=](double t) {
    double a = I;
    for (double start = 0;; start += M_PI) {
      if (std::abs(a) <= mu) return a;
      const double center = mu * sign(a);
      if (t <= start + M_PI) return center + (a - center) * std::cos(t - start);
      a = 2 * center - a;
    }
  };
}
}  // namespace

// m u'' + mu m g sign(u') + s(u) = 0, scaled with u_c = I, t_c = sqrt(m/k)
// (section 1.12.3, Exercise 1.23).
ModelDefinition sliding_box_model() {
  ModelDefinition m;
  m.name = "sliding-box";
  m.equation = R"(u'' + \mu\,\mathrm{sign}(u') + s(u) = 0)";
  m.equation_for = [](const Parameters& p) -> std::string {
    if (p.number("alpha") == 0) return R"(u'' + \mu\,\mathrm{sign}(u') + u = 0)";
    return R"(u'' + \mu\,\mathrm{sign}(u') + \frac{\tanh(\alpha u)}{\alpha} = 0)";
  };
  m.summary = "box on a spring sliding with Coulomb friction, scaled (section 1.12.3); turning points located exactly";
  m.keys = {
      {"mu", ValueKind::number, "0.08", "", "friction mu m g / (k I): against the initial spring force", {}, {}},
      {"alpha", ValueKind::number, "0", "", "spring nonlinearity alpha I: s = tanh(alpha u)/alpha; 0 = linear", {}, {}},
      {"I", ValueKind::number, "1", "", "initial displacement u(0) (the length unit, so 1 unless comparing)", {}, {}},
      {"V", ValueKind::number, "0", "", "initial velocity u'(0)", {}, {}},
  };
  m.columns = {"t", "u", "v"};
  m.time_defaults = {"centered", "60", "4"};
  m.build = [columns = m.columns, name = m.name](const Parameters& p) -> std::unique_ptr<Trajectory> {
    auto law = std::make_shared<SlidingBoxLaw>();
    law->mu = p.number("mu"), law->alpha = p.number("alpha");
    const double I = p.number("I"), V = p.number("V");
    if (!(law->mu >= 0) || std::isinf(law->mu)) throw UsageError("mu=" + p.text("mu") + " must be >= 0");
    if (!(law->alpha >= 0) || std::isinf(law->alpha)) throw UsageError("alpha=" + p.text("alpha") + " must be >= 0");
    if (!std::isfinite(I) || !std::isfinite(V)) throw UsageError("I and V must be finite numbers");
    TrajectoryInfo info;
    info.columns = columns;
    info.mesh = resolve_time_mesh(p, 2 * M_PI, 1.0);
    reject_adjusted_scheme(info.mesh, name);
    // Friction only takes energy out: the swing stays where the spring's
    // potential holds the initial energy (beyond sqrt(2 E) when alpha > 0
    // softens the spring).
    const double E0 = law->potential(I) + 0.5 * V * V;
    if (E0 > 0)
      info.amplitude_bound = potential_reach([law](double u) { return law->potential(u); }, I, E0,
                                             std::max({std::abs(I), std::abs(V), 1e-3}) / 8);
    if (law->alpha == 0 && V == 0) info.exact = released_from_rest(I, law->mu), info.exact_label = "exact";
    info.damped = law->mu > 0;
    info.energy = [law](std::span<const double> row) {
      return EnergyParts{0.5 * row[2] * row[2], law->potential(row[1])};
    };
    info.energy_unit = "k I^2";
    info.spring_and_friction = TrajectoryInfo::SpringAndFriction{[law](double u) { return law->spring(u); }, law->mu};

    // The friction of the current half swing: -mu times its direction.
    auto direction = std::make_shared<double>(0);
    EventLaw events;
    events.system = std::make_shared<SecondOrderSystem<1>>(SecondOrderSystem<1>::general(
        [law, direction](const Vec<1>& u, double) { return Vec<1>(-law->mu * *direction - law->spring(u[0])); }));
    events.event_value = [](double, double v) { return v; };
    events.on_event = [law, direction](double, double u, double) {
      EventOutcome out{u, 0, 1, law->holds(u)};
      *direction = out.direction = -sign(law->spring(u));
      return out;
    };
    EventOutcome start{I, V, sign(V), false};
    if (V == 0) start = events.on_event(0, I, 0);
    *direction = start.direction;
    return std::make_unique<EventTrajectory>(events, I, V, start, info, [](const Sample<1>& x, std::span<double> out) {
      out[0] = x.t, out[1] = x.u[0], out[2] = x.v[0];
    });
  };
  return m;
}

}  // namespace vibra
