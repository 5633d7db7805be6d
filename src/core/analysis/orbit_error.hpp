#pragma once
#include <functional>
#include <string>
#include <vector>

namespace vibra {

/// The largest position error over a block of orbits.
struct OrbitBlock {
  long long orbits;  ///< orbits completed at the block's end
  double max_error;
};

/// A run of the circular orbit (Exercise 1.28).
struct OrbitRun {
  int steps_per_orbit;
  double dt;
  double max_error;    ///< max_n |(x^n, y^n) - (cos t_n, sin t_n)| over the run
  double cpu_seconds;  ///< CPU time of the run, error measurement included
  std::vector<OrbitBlock> blocks;
};

/// Model two-body from (1, 0) with velocity (0, 1): the circular orbit
/// x = cos t, y = sin t of period 2 pi, for `orbits` orbits with the scheme
/// named `scheme`. Records the largest error per block of `block_orbits`
/// orbits and calls `progress(orbits done)` after each block. Streams.
OrbitRun circular_orbit_run(const std::string& scheme, int steps_per_orbit, long long orbits, long long block_orbits,
                            const std::function<void(long long)>& progress = {});

}  // namespace vibra
