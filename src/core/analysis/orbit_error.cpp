// The two-body orbit's errors per block of orbits: radius drift and phase drift.
#include "core/analysis/orbit_error.hpp"

#include <algorithm>
#include <cmath>
#include <ctime>

#include "core/error.hpp"
#include "core/models/model.hpp"

namespace vibra {

OrbitRun circular_orbit_run(const std::string& scheme, int steps_per_orbit, long long orbits, long long block_orbits,
                            const std::function<void(long long)>& progress) {
  if (steps_per_orbit < 4) throw UsageError("steps per orbit must be >= 4, e.g. --steps-per-orbit 200,400");
  if (orbits < 1 || block_orbits < 1) throw UsageError("the number of orbits must be >= 1, e.g. --orbits 100");
  const ModelDefinition& model = find_model("two-body");
  Parameters p = model_parameters(model);
  p.set("scheme", scheme);
  p.set("steps_per_period", std::to_string(steps_per_orbit));
  p.set("periods", std::to_string(orbits));
  for (const char* key : {"x0=1", "y0=0", "vx0=0", "vy0=1"}) p.assign(key);

  const std::clock_t start = std::clock();
  auto trajectory = model.build(p);
  require_even_steps(trajectory->info().mesh, "analyze orbit, which counts steps per orbit,");
  OrbitRun run{steps_per_orbit, trajectory->info().mesh.dt, 0, 0, {}};
  const long long steps_per_block = block_orbits * steps_per_orbit;
  std::vector<double> row(trajectory->width());
  double block_error = 0, block_energy = 0, phase = 0;
  do {
    trajectory->row(row);
    const double t = row[0], x = row[1], y = row[2], vx = row[3], vy = row[4];
    const double dx = x - std::cos(t), dy = y - std::sin(t);
    block_error = std::max(block_error, std::sqrt(dx * dx + dy * dy));
    block_energy = std::max(block_energy, std::abs(0.5 * (vx * vx + vy * vy) - 1 / std::hypot(x, y) + 0.5));
    const long long n = trajectory->index();
    if (n > 0 && (n % steps_per_block == 0 || trajectory->done())) {
      const long long done = (n + steps_per_orbit - 1) / steps_per_orbit;
      // The change since the last block is far below pi: take the nearest branch.
      phase += std::remainder(std::atan2(y, x) - t - phase, 2 * M_PI);
      run.blocks.push_back({done, block_error, phase, block_energy});
      run.max_error = std::max(run.max_error, block_error);
      block_error = block_energy = 0;
      if (progress) progress(done);
    }
  } while (trajectory->advance());
  run.cpu_seconds = double(std::clock() - start) / CLOCKS_PER_SEC;
  return run;
}

}  // namespace vibra
