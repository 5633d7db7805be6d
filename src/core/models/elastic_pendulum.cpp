// The elastic-pendulum model (section 1.12.7, (1.148)): a pendulum on a spring, in scaled (x, y).
#include <cmath>

#include "core/error.hpp"
#include "core/models/model.hpp"

namespace vibra {

namespace {
/// The angle of `raw` (any turn) nearest `reference`: the wire's angle taken
/// whole turns on from the last row, so theta stays continuous through +-180
/// degrees and counts the turns of a pendulum that goes over the top. Rows
/// come in time order (the pre-pass, then the frames, each from a fresh run),
/// and a step turns the wire far less than half a turn.
double nearest_turn(double raw, double reference) {
  return raw + 2 * M_PI * std::round((reference - raw) / (2 * M_PI));
}
}  // namespace

// The elastic pendulum (1.132)-(1.148), scaled: pivot at (0, 1), equilibrium
// at the origin, beta = L0 / (L0 + m g / k).
ModelDefinition elastic_pendulum_model() {
  ModelDefinition m;
  m.name = "elastic-pendulum";
  m.equation = R"(x'' = -\frac{\beta}{1 - \beta}(1 - \frac{\beta}{L})x,\quad L = \sqrt{x^2 + (y - 1)^2} \\ y'' = -\frac{\beta}{1 - \beta}(1 - \frac{\beta}{L})(y - 1) - \beta)";
  m.equation_for = [](const Parameters& p) -> std::string {
    if (p.number("gamma") == 0)
      return R"(x'' = -\frac{\beta}{1 - \beta}(1 - \frac{\beta}{L})x,\quad L = \sqrt{x^2 + (y - 1)^2} \\ )"
             R"(y'' = -\frac{\beta}{1 - \beta}(1 - \frac{\beta}{L})(y - 1) - \beta)";
    return R"(x'' = -\frac{\beta}{1 - \beta}(1 - \frac{\beta}{L})x - \frac{\gamma}{\beta}|v|x',\quad L = \sqrt{x^2 + (y - 1)^2} \\ )"
           R"(y'' = -\frac{\beta}{1 - \beta}(1 - \frac{\beta}{L})(y - 1) - \beta - \frac{\gamma}{\beta}|v|y')";
  };
  m.summary = "pendulum on an elastic wire (1.148), scaled, with optional air drag (Exercise 1.27); "
              "steps_per_period and periods use the book's period P = 2 pi (Exercise 1.26)";
  m.keys = {
      {"beta", ValueKind::number, "0.9", "", "L0/(L0 + mg/k), 0 < beta < 1 (beta -> 1 is a rigid wire)", {}, {}},
      {"Theta", ValueKind::angle, "30", "deg", "initial angle (suffix rad for radians)", {}, {}},
      {"eps", ValueKind::number, "0", "", "initial extra stretch of the wire", {}, {}},
      {"gamma", ValueKind::number, "0", "", "scaled air drag L0 rho C_D pi R^2 / (2 m)", {}, {}},
  };
  m.columns = {"t", "x", "y", "vx", "vy", "theta"};
  m.time_defaults = {"rk4", "60", "10"};
  m.build = [columns = m.columns, name = m.name](const Parameters& p) -> std::unique_ptr<Trajectory> {
    const double beta = p.positive("beta"), Theta = p.angle("Theta"), eps = p.number("eps"), gamma = p.number("gamma");
    if (beta >= 1) throw UsageError("beta must be < 1 (beta = 1 is the rigid wire: use model pendulum)");
    if (gamma < 0) throw UsageError("gamma must be >= 0");
    if (eps <= -1) throw UsageError("eps must be > -1 (the wire cannot have negative length)");
    const double pendulum_w = std::sqrt(beta), spring_w = std::sqrt(beta / (1 - beta));

    TrajectoryInfo info;
    info.columns = columns;
    // The book's period is P = 2 pi in the time unit sqrt(L0/g) (Exercise 1.26),
    // the rigid pendulum's; the elastic one swings at about sqrt(beta).
    info.mesh = resolve_time_mesh(p, 2 * M_PI, std::max(pendulum_w, spring_w));
    reject_adjusted_scheme(info.mesh, name);
    info.amplitude_bound = (1 + std::abs(eps)) * std::abs(std::sin(Theta)) + std::abs(eps);

    auto system = std::make_shared<SecondOrderSystem<2>>(SecondOrderSystem<2>::general([beta](const Vec<2>& u, double) -> Vec<2> {
      const double x = u[0], y = u[1];
      const double L = std::hypot(x, y - 1);
      // (1 - beta/L)/(1 - beta) = (L - 1)/(L (1 - beta)) + 1/L, with
      // L - 1 = (x^2 + y^2 - 2y)/(L + 1) free of cancellation as beta -> 1.
      const double stretch = (x * x + y * y - 2 * y) / (L + 1);
      const double factor = beta * (stretch / (L * (1 - beta)) + 1 / L);
      return Vec<2>(-factor * x, -factor * (y - 1) - beta);
    }));
    system->damping = gamma > 0 ? Damping::quadratic : Damping::none;
    info.damped = gamma > 0;
    // Gravity beta y plus the wire's 0.5 beta/(1 - beta) (L - beta)^2, whose
    // gradient is the force above; conserved without drag.
    info.energy = [beta](std::span<const double> row) {
      const double x = row[1], y = row[2], stretch = std::hypot(x, y - 1) - beta;
      return EnergyParts{0.5 * (row[3] * row[3] + row[4] * row[4]), beta * y + 0.5 * beta / (1 - beta) * stretch * stretch};
    };
    info.energy_unit = "m g L0 / beta^2";
    system->damping_per_mass = gamma / beta;
    const Vec<2> u0((1 + eps) * std::sin(Theta), 1 - (1 + eps) * std::cos(Theta));
    // theta from the downward vertical at the pivot (0, 1), over all four
    // quadrants (atan2: the bob above the pivot is past 90 degrees), unwrapped.
    return std::make_unique<SecondOrderTrajectory<2>>(
        system, u0, Vec<2>::Zero(), info, [last = Theta](const Sample<2>& s, std::span<double> out) mutable {
          out[0] = s.t, out[1] = s.u[0], out[2] = s.u[1], out[3] = s.v[0], out[4] = s.v[1];
          last = out[5] = nearest_turn(std::atan2(s.u[0], 1 - s.u[1]), last);
        });
  };
  return m;
}

}  // namespace vibra
