// The bouncing-ball model (section 1.12.9, Exercise 1.24): free fall with impacts located between steps.
#include <cmath>
#include <string>

#include "core/error.hpp"
#include "core/event_trajectory.hpp"
#include "core/models/model.hpp"

namespace vibra {

namespace {
/// Schemes whose step is exact for h'' = -g, so the Hermite interpolant of a
/// step is the parabola itself and impacts are located to rounding. The
/// first-order schemes (Forward and Backward Euler, plain Euler-Cromer) err
/// by O(dt) in every flight.
bool exact_for_free_fall(Scheme s) {
  return s != Scheme::forward_euler && s != Scheme::backward_euler && s != Scheme::euler_cromer;
}

/// The exact height: free flights between impacts, the n-th rebound C_R^n
/// times the first impact speed, rest at the first rebound slower than eps_v
/// (section 1.12.9, docs/scenes-2d.md).
std::function<double(double)> exact_height(double h0, double V, double g, double C_R, double eps_v) {
  return [=](double t) {
    const double t1 = (V + std::sqrt(V * V + 2 * g * h0)) / g;
    if (t <= t1) return std::max(0.0, h0 + V * t - 0.5 * g * t * t);
    double speed = std::sqrt(V * V + 2 * g * h0), start = t1;
    for (int n = 1; n < 100000; ++n) {
      speed *= C_R;
      if (speed < eps_v) return 0.0;
      const double flight = 2 * speed / g, s = t - start;
      if (s <= flight) return std::max(0.0, speed * s - 0.5 * g * s * s);
      start += flight;
    }
    return 0.0;
  };
}
}  // namespace

// h'' = -g in flight; at h = 0 moving down, v -> -C_R v (section 1.12.9,
// Exercise 1.24). Impacts are events located inside the step.
ModelDefinition bouncing_ball_model() {
  ModelDefinition m;
  m.name = "bouncing-ball";
  m.equation = R"(h'' = -g,\quad h'\to -C_R h' \text{ at } h = 0)";
  m.time_unit = "s";
  m.summary = "ball bouncing on the ground, h'' = -g, restitution C_R (section 1.12.9); impacts located exactly";
  m.keys = {
      {"h0", ValueKind::number, "1", "m", "initial height h(0) >= 0", {}, {}},
      {"V", ValueKind::number, "0", "m/s", "initial velocity h'(0), positive upward", {}, {}},
      {"g", ValueKind::number, "9.81", "m/s^2", "acceleration of gravity", {}, {}},
      {"C_R", ValueKind::number, "0.8", "", "coefficient of restitution: rebound speed / impact speed, 0 <= C_R < 1", {}, {}},
      {"eps_v", ValueKind::number, "0.01", "m/s", "the ball rests at the first impact whose rebound speed is below this", {}, {}},
  };
  m.columns = {"t", "h", "v"};
  m.time_defaults = {"centered", "100", "6"};
  m.build = [columns = m.columns, name = m.name](const Parameters& p) -> std::unique_ptr<Trajectory> {
    const double h0 = p.number("h0"), V = p.number("V"), g = p.positive("g");
    const double C_R = p.number("C_R"), eps_v = p.positive("eps_v");
    if (!(h0 >= 0) || !std::isfinite(h0)) throw UsageError("h0=" + p.text("h0") + " must be a finite height >= 0");
    if (!std::isfinite(V)) throw UsageError("V=" + p.text("V") + " must be a finite number");
    if (!(C_R >= 0 && C_R < 1)) throw UsageError("C_R=" + p.text("C_R") + " must be in [0, 1) (1 would bounce forever)");
    if (!std::isfinite(eps_v)) throw UsageError("eps_v=" + p.text("eps_v") + " must be a finite speed > 0");
    // The period is the first fall and rise from the highest point, h0 + V^2/(2g).
    const double apex = h0 + V * V / (2 * g);
    TrajectoryInfo info;
    info.columns = columns;
    info.mesh = resolve_time_mesh(p, apex > 0 ? 2 * std::sqrt(2 * apex / g) : 0, 0);
    reject_adjusted_scheme(info.mesh, name);
    if (!exact_for_free_fall(info.mesh.scheme))
      throw UsageError("scheme=" + std::string(scheme_info(info.mesh.scheme).name) +
                       " does not integrate free fall exactly, so impacts would drift: use a second-order scheme "
                       "such as centered, velocity-verlet or rk4");
    info.amplitude_bound = apex;
    info.exact = exact_height(h0, V, g, C_R, eps_v), info.exact_label = "exact";
    info.damped = C_R < 1;  // impacts take energy out
    info.energy = [g](std::span<const double> row) { return EnergyParts{0.5 * row[2] * row[2], g * row[1]}; };
    info.energy_unit = "J/kg";

    EventLaw events;
    events.system = std::make_shared<SecondOrderSystem<1>>(
        SecondOrderSystem<1>::general([g](const Vec<1>&, double) { return Vec<1>(-g); }));
    events.event_value = [](double h, double) { return h; };
    events.on_event = [C_R, eps_v](double, double, double v) {
      const double rebound = -C_R * v;
      return EventOutcome{0, rebound, 1, !(rebound >= eps_v)};
    };
    EventOutcome start{h0, V, 1, false};
    if (h0 == 0 && V <= 0) start = V < 0 ? events.on_event(0, 0, V) : EventOutcome{0, 0, 1, true};
    // The located impact lies within rounding of h = 0 on either side: never print h < 0.
    return std::make_unique<EventTrajectory>(events, start.u, start.v, start, info,
                                             [](const Sample<1>& x, std::span<double> out) {
                                               out[0] = x.t, out[1] = std::max(0.0, x.u[0]), out[2] = x.v[0];
                                             });
  };
  return m;
}

}  // namespace vibra
