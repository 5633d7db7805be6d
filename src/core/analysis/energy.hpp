// The energy error max |e_E^n| / E(0) of u'' + w^2 u = 0 (1.49), with u' from centered differences.
#pragma once
#include "core/trajectory.hpp"

namespace vibra {

/// max_n |e_E^n| / E(0) for u'' + w^2 u = 0 (1.49), n = 1..Nt-1, with u' from
/// the centered difference of u whatever the scheme, as the book's table does.
/// Streams the trajectory (constant memory).
double max_relative_energy_error(Trajectory&, double w, double I, double V);

}  // namespace vibra
