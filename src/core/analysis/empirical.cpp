// Empirical periods and amplitudes from the extrema of a sampled solution.
#include "core/analysis/empirical.hpp"

#include <cmath>

namespace vibra {

EmpiricalOscillation::Extremum EmpiricalOscillation::locate(double dt) const {
  const double before = u_[0], here = u_[1], after = u_[2];
  if (timing_ == ExtremumTiming::fitted) {
    // A cos(theta s + phi) at s = -1, 0, 1: before + after = 2 here cos(theta),
    // after - before = -2 A sin(phi) sin(theta); the extremum is at s = -phi/theta.
    const double c = here != 0 ? (before + after) / (2 * here) : 2;
    if (c > -1 && c < 1) {
      const double theta = std::acos(c);
      const double phi = std::atan((before - after) / (2 * here * std::sin(theta)));
      return {t_[1] - phi / theta * dt, here / std::cos(phi)};
    }
    // Not a sinusoid about zero: the parabola through the three samples.
    const double curvature = before - 2 * here + after;
    if (curvature != 0) {
      const double s = (before - after) / (2 * curvature);
      return {t_[1] + s * dt, here - 0.25 * (before - after) * s};
    }
  }
  return {t_[1], here};
}

std::optional<OscillationCycle> EmpiricalOscillation::add(double t, double u) {
  t_[0] = t_[1], t_[1] = t_[2], t_[2] = t;
  u_[0] = u_[1], u_[1] = u_[2], u_[2] = u;
  if (++samples_ < 3) return std::nullopt;
  const double dt = t_[2] - t_[1];
  if (u_[0] < u_[1] && u_[1] > u_[2]) maxima_.push_back(locate(dt));
  if (u_[0] > u_[1] && u_[1] < u_[2]) minima_.push_back(locate(dt));
  if (maxima_.size() < 2 || minima_.empty()) return std::nullopt;
  const OscillationCycle cycle{cycles_++, maxima_[0].t, maxima_[1].t - maxima_[0].t,
                               std::abs(maxima_[0].u - minima_[0].u) / 2};
  maxima_.pop_front();
  minima_.pop_front();
  return cycle;
}

std::vector<OscillationCycle> oscillation_cycles(Trajectory& trajectory, ExtremumTiming timing) {
  require_even_steps(trajectory.info().mesh, "locating extrema (analyze empirical, amplitude), which fits three evenly spaced samples,");
  EmpiricalOscillation oscillation(timing);
  std::vector<OscillationCycle> cycles;
  std::vector<double> row(trajectory.width());
  do {
    trajectory.row(row);
    if (auto cycle = oscillation.add(row[0], row[1])) cycles.push_back(*cycle);
  } while (trajectory.advance());
  return cycles;
}

}  // namespace vibra
