// The two-body orbit's errors per block of orbits: radius drift and phase drift.
#pragma once
#include <functional>
#include <string>
#include <vector>

namespace vibra {

/// What a block of orbits shows of the error.
struct OrbitBlock {
  long long orbits;  ///< orbits completed at the block's end
  double max_error;  ///< the largest position error in the block
  /// The angle's error at the block's end, atan2(y, x) - t, followed
  /// continuously from block to block (radians; positive: ahead).
  double phase;
  /// The largest |E - E(0)| in the block, E = |v|^2/2 - 1/|x|, E(0) = -1/2.
  double energy_error;
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
/// named `scheme`. Records each block of `block_orbits` orbits (largest
/// position error, phase error at its end, largest energy error) and calls `progress(orbits done)` after each block. Streams.
OrbitRun circular_orbit_run(const std::string& scheme, int steps_per_orbit, long long orbits, long long block_orbits,
                            const std::function<void(long long)>& progress = {});

}  // namespace vibra
