// The energy error max |e_E^n| / E(0) of u'' + w^2 u = 0 (1.49), with u' from centered differences.
#include "core/analysis/energy.hpp"

#include <cmath>
#include <vector>

namespace vibra {

double max_relative_energy_error(Trajectory& trajectory, double w, double I, double V) {
  const double E0 = 0.5 * V * V + 0.5 * w * w * I * I;
  const double dt = trajectory.info().mesh.dt;
  require_even_steps(trajectory.info().mesh, "the energy error (1.49), a centered difference of u,");
  std::vector<double> row(trajectory.width());
  trajectory.row(row);
  double before = row[1];
  if (!trajectory.advance()) return 0;
  trajectory.row(row);
  double here = row[1];
  double worst = 0;
  while (trajectory.advance()) {
    trajectory.row(row);
    const double after = row[1];
    const double v = (after - before) / (2 * dt);
    worst = std::max(worst, std::abs(0.5 * v * v + 0.5 * w * w * here * here - E0));
    before = here, here = after;
  }
  return worst / E0;
}

}  // namespace vibra
