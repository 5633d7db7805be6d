// The pendulum and physical-pendulum models: theta'' + alpha |theta'| theta' + sin(theta) = 0, scaled.
#include <cmath>

#include "core/analysis/frequency/pendulum_period.hpp"
#include "core/error.hpp"
#include "core/models/model.hpp"

namespace vibra {

namespace {
/// Largest angle reached from (Theta, Omega) without drag, from energy
/// conservation: 1 - cos(theta_max) = 1 - cos(Theta) + Omega^2/2. 0 when the
/// pendulum goes over the top.
double swing_bound(double Theta, double Omega) {
  const double c = std::cos(Theta) - 0.5 * Omega * Omega;
  return c > -1 ? std::acos(c) : 0;
}

std::vector<KeySpec> angle_keys(const std::string& Theta_default) {
  return {{"Theta", ValueKind::angle, Theta_default, "deg", "initial angle from the downward vertical (suffix rad for radians)", {}, {}},
          {"Omega", ValueKind::angle, "0", "deg/time", "initial angular velocity (suffix rad for radians)", {}, {}}};
}

/// The pendulums share the scaled equation theta'' + alpha |theta'| theta' +
/// sin(theta) = 0; `energy_unit` names what scales their energy 0.5 omega^2 + 1 - cos(theta).
std::unique_ptr<Trajectory> pendulum_trajectory(const Parameters& p, const std::vector<std::string>& columns,
                                                const std::string& name, double alpha, double wire_factor,
                                                const std::string& energy_unit) {
  const double Theta = p.angle("Theta"), Omega = p.angle("Omega");
  if (alpha < 0) throw UsageError("the drag coefficient alpha must be >= 0");
  TrajectoryInfo info;
  info.columns = columns;
  info.mesh = resolve_time_mesh(p, 2 * M_PI, 1.0);
  reject_adjusted_scheme(info.mesh, name);
  info.amplitude_bound = swing_bound(Theta, Omega);
  if (alpha == 0) {
    info.exact = [=](double t) { return Theta * std::cos(t) + Omega * std::sin(t); };
    info.exact_label = "small-angle";
    if (info.amplitude_bound > 0) info.exact_period = pendulum_period(info.amplitude_bound);
    info.exact_period_label = "4<i>K</i>(sin <i>Θ</i>/2)";
  }
  info.small_period_label = "2π, small angles";
  info.damped = alpha > 0;
  info.energy = [](std::span<const double> row) {
    const double theta = row[1], omega = row[2], half_sine = std::sin(0.5 * theta);
    return EnergyParts{0.5 * omega * omega, 2 * half_sine * half_sine};  // 1 - cos(theta) without cancellation
  };
  info.energy_unit = energy_unit;
  // Scaled (1.131): theta'' = -sin(theta) - alpha |theta'| theta'.
  auto system = std::make_shared<SecondOrderSystem<1>>(SecondOrderSystem<1>::sine(1.0));
  system->damping = alpha > 0 ? Damping::quadratic : Damping::none;
  system->damping_per_mass = alpha;
  return std::make_unique<SecondOrderTrajectory<1>>(
      system, Vec<1>(Theta), Vec<1>(Omega), info, [=](const Sample<1>& s, std::span<double> out) {
        const double theta = s.u[0], omega = s.v[0];
        out[0] = s.t, out[1] = theta, out[2] = omega;
        out[3] = wire_factor * omega * omega + std::cos(theta);  // S / (m g)
        out[4] = -alpha * std::abs(omega) * omega;               // D / (m g), along i_theta
      });
}
}  // namespace

// The pendulum with air drag, scaled (1.124)-(1.131).
ModelDefinition pendulum_model() {
  ModelDefinition m;
  m.name = "pendulum";
  m.equation = R"(\theta'' + \alpha|\theta'|\theta' + \sin\theta = 0)";
  m.equation_for = [](const Parameters& p) -> std::string {
    if (p.given("alpha") && p.number("alpha") == 0) return R"(\theta'' + \sin\theta = 0)";
    return R"(\theta'' + \alpha|\theta'|\theta' + \sin\theta = 0)";
  };
  m.summary = "pendulum with quadratic air drag, scaled (1.131); wire force S and drag D in units of mg";
  m.keys = angle_keys("70");
  std::vector<KeySpec> more = {
      {"alpha", ValueKind::number, "0.4", "", "scaled drag C_D rho pi R^2 L / (2 m)", {}, {}},
      {"L", ValueKind::number, "", "m", "wire length (with m and R: alpha from physical data)", {}, {}},
      {"m", ValueKind::number, "", "kg", "bob mass", {}, {}},
      {"R", ValueKind::number, "", "m", "bob radius", {}, {}},
      {"C_D", ValueKind::number, "0.4", "", "drag coefficient (sphere 0.4)", {}, {}},
      {"rho", ValueKind::number, "1.2", "kg/m^3", "air density", {}, {}},
      {"g", ValueKind::number, "9.81", "m/s^2", "gravity (time unit is sqrt(L/g))", {}, {}},
  };
  m.keys.insert(m.keys.end(), more.begin(), more.end());
  m.columns = {"t", "theta", "omega", "S", "D"};
  m.time_defaults = {"rk4", "60", "10"};
  m.build = [columns = m.columns, name = m.name](const Parameters& p) {
    double alpha = p.number("alpha");
    const bool physical = p.given("L") || p.given("m") || p.given("R");
    if (physical) {
      if (!(p.given("L") && p.given("m") && p.given("R")))
        throw UsageError("physical data needs L, m and R together (and optionally C_D, rho, g)");
      if (p.given("alpha")) throw UsageError("give either alpha or the physical data L, m, R, not both");
      alpha = p.positive("C_D") * p.positive("rho") * M_PI * std::pow(p.positive("R"), 2) * p.positive("L") /
              (2 * p.positive("m"));
      p.positive("g");
    }
    return pendulum_trajectory(p, columns, name, alpha, 1.0, "m g L");
  };
  return m;
}

// A rigid rod of mass m_rod with a bob of mass m_bob at its end, swinging
// about one end: I_P theta'' + c |theta'| theta' + M g L_cm sin(theta) = 0,
// scaled by t_c = sqrt(I_P / (M g L_cm)).
ModelDefinition physical_pendulum_model() {
  ModelDefinition m;
  m.name = "physical-pendulum";
  m.equation = R"(I_P\theta'' + c|\theta'|\theta' + M g L_{cm}\sin\theta = 0)";
  m.summary = "rod with mass (and an optional bob) swinging about its end, with air drag on the bob";
  m.keys = angle_keys("70");
  std::vector<KeySpec> more = {
      {"L", ValueKind::number, "1", "m", "rod length", {}, {}},
      {"m_rod", ValueKind::number, "1", "kg", "rod mass", {}, {}},
      {"m_bob", ValueKind::number, "0", "kg", "point mass at the rod's end", {}, {}},
      {"R", ValueKind::number, "0.05", "m", "radius of the sphere at the end that meets the air", {}, {}},
      {"C_D", ValueKind::number, "0.4", "", "drag coefficient", {}, {}},
      {"rho", ValueKind::number, "1.2", "kg/m^3", "air density", {}, {}},
  };
  m.keys.insert(m.keys.end(), more.begin(), more.end());
  m.columns = {"t", "theta", "omega", "S", "D"};
  m.time_defaults = {"rk4", "60", "10"};
  m.build = [columns = m.columns, name = m.name](const Parameters& p) {
    const double L = p.positive("L"), m_rod = p.number("m_rod"), m_bob = p.number("m_bob");
    if (m_rod < 0 || m_bob < 0 || m_rod + m_bob <= 0)
      throw UsageError("masses must be >= 0 with m_rod + m_bob > 0");
    const double M = m_rod + m_bob;
    const double moment = m_rod * L * L / 3 + m_bob * L * L;    // about the pivot
    const double L_cm = (0.5 * m_rod * L + m_bob * L) / M;      // pivot to centre of mass
    const double c = 0.5 * p.positive("C_D") * p.positive("rho") * M_PI * std::pow(p.number("R"), 2) * L * L * L;
    // S is the pivot force along the rod over M g: cos(theta) + M L_cm^2 / I_P omega^2.
    // Energy 0.5 I_P theta_t^2 + M g L_cm (1 - cos theta) with theta_t = omega / t_c
    // is M g L_cm (0.5 omega^2 + 1 - cos theta): the scaled pendulum's, in units of M g L_cm.
    return pendulum_trajectory(p, columns, name, c / moment, M * L_cm * L_cm / moment,
                               "M g L_cm (total mass, pivot to centre of mass)");
  };
  return m;
}

}  // namespace vibra
