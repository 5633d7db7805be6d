// TimeMesh: t_n = n dt up to T and the scheme that walks it, with the adaptive tolerances checked.
#include "core/time_mesh.hpp"

#include <cmath>
#include <cstdio>

#include "core/error.hpp"
#include "core/solution_stream.hpp"

namespace vibra {

std::vector<KeySpec> time_keys(const TimeDefaults& defaults) {
  std::vector<std::string> scheme_names;
  for (const auto& info : all_schemes()) scheme_names.emplace_back(info.name);
  return {
      {"scheme", ValueKind::choice, defaults.scheme, "", "time-stepping scheme", scheme_names, {}},
      {"dt", ValueKind::number, "", "time", "time step (overrides steps_per_period)", {}, {}},
      {"steps_per_period", ValueKind::number, defaults.steps_per_period, "", "time steps per small-oscillation period", {}, {}},
      {"T", ValueKind::number, "", "time", "end time, inf for an endless run (overrides periods)", {}, {}},
      {"periods", ValueKind::number, defaults.periods, "", "end time in small-oscillation periods", {}, {}},
      {"rtol", ValueKind::number, "1e-6", "", "relative tolerance per step of rkf45 and dopri5", {}, {}},
      {"atol", ValueKind::number, "1e-9", "", "absolute tolerance per step of rkf45 and dopri5 (in u's and v's units)", {}, {}},
  };
}

namespace {
std::string g(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", x);
  return buf;
}

bool unstable_allowed = false;

/// The tolerances, checked: below 1e-14 (about 45 machine epsilons) the
/// rounding of a step's error estimate is as large as the tolerance, and
/// the step size would shrink until the run fails (docs/schemes.md). A tiny
/// atol is fine: rtol keeps each component's tolerance above rounding.
void read_tolerances(const Parameters& p, TimeMesh& mesh) {
  mesh.rtol = p.number("rtol");
  mesh.atol = p.number("atol");
  if (!(mesh.rtol >= 1e-14 && mesh.rtol < 1))
    throw UsageError("rtol=" + p.text("rtol") +
                     " is out of range: give a relative tolerance in [1e-14, 1) (doubles resolve no finer), e.g. rtol=1e-8");
  if (!(mesh.atol >= 0 && std::isfinite(mesh.atol)))
    throw UsageError("atol=" + p.text("atol") + " is out of range: give an absolute tolerance >= 0, e.g. atol=1e-12");
}
}  // namespace

void allow_unstable_steps(bool allowed) { unstable_allowed = allowed; }

void require_even_steps(const TimeMesh& mesh, const std::string& analysis) {
  if (mesh.adaptive())
    throw UsageError(analysis + " needs the even steps of a fixed-step scheme, and " +
                     std::string(scheme_info(mesh.scheme).name) +
                     " chooses its own: choose another scheme, e.g. scheme=rk4");
}

TimeMesh resolve_time_mesh(const Parameters& p, double period, double fastest_w) {
  TimeMesh mesh;
  mesh.scheme = parse_scheme(p.text("scheme"));
  mesh.period = period;
  const bool has_period = period > 0 && std::isfinite(period);

  if (p.given("dt") && p.given("steps_per_period"))
    throw UsageError("give either dt or steps_per_period, not both");
  if (p.given("T") && p.given("periods")) throw UsageError("give either T or periods, not both");
  if (p.given("dt")) {
    mesh.dt = p.positive("dt");
  } else if (has_period) {
    mesh.dt = period / p.positive("steps_per_period");
  } else {
    throw UsageError(p.owner() + " has no oscillation period with these parameters: give dt");
  }
  if (p.given("T")) {
    mesh.T = p.positive("T", true);
  } else if (has_period) {
    mesh.T = period * p.positive("periods", true);
  } else {
    throw UsageError(p.owner() + " has no oscillation period with these parameters: give T");
  }

  read_tolerances(p, mesh);

  const double limit = stability_limit(mesh.scheme, fastest_w);
  if (limit > 0 && mesh.dt > limit) {
    const std::string problem = "dt=" + g(mesh.dt) + " is above the stability limit " + g(limit) + " of scheme " +
                                std::string(scheme_info(mesh.scheme).name) + " for this problem";
    if (unstable_allowed) {
      static bool warned = false;  // once, though a render builds its runs twice
      if (!warned) std::fprintf(stderr, "vibra: warning: %s: the solution will grow (--allow-unstable)\n", problem.c_str());
      warned = true;
    } else {
      std::string advice = "use dt <= " + g(limit);
      if (has_period) advice += " (steps_per_period >= " + g(std::ceil(period / limit)) + ")";
      throw UsageError(problem + ": " + advice + ", or draw the growth with --allow-unstable");
    }
  }

  if (std::isinf(mesh.T)) {
    mesh.steps = SolutionStream<1>::unbounded;
  } else {
    const double steps = std::round(mesh.T / mesh.dt);
    if (steps > 1e15) throw UsageError("T/dt = " + g(steps) + " steps is too many: use T=inf for an endless run");
    mesh.steps = std::max(1LL, static_cast<long long>(steps));
    mesh.T = mesh.steps * mesh.dt;
  }
  return mesh;
}

}  // namespace vibra
