// EnergyParts: a system's mechanical energy at one instant, split into kinetic and potential.
#pragma once
#include <cmath>
#include <functional>
#include <span>

namespace vibra {

/// A system's mechanical energy at one instant, split so that panels and bars
/// can show where it sits. Each model defines both parts from one of its
/// solution rows, with the scheme's own velocity (so a scheme that gains or
/// loses energy shows it). The unit is the model's: TrajectoryInfo::energy_unit.
struct EnergyParts {
  double kinetic = 0;
  double potential = 0;  ///< zero where the model puts its reference level
  double total() const { return kinetic + potential; }
};

/// Energy from a row of the model's columns (t first), as Trajectory::row writes it.
using EnergyFunction = std::function<EnergyParts(std::span<const double> row)>;

/// (E - E(0)) / |E(0)|: the relative change of the energy since the start,
/// positive when energy was gained (|E(0)| so that this holds for the negative
/// energy of a bound orbit too). NaN when E(0) = 0 (a system at rest at its
/// reference level, where no relative change exists).
inline double relative_energy_change(double E, double E0) { return E0 != 0 ? (E - E0) / (E0 < 0 ? -E0 : E0) : NAN; }

}  // namespace vibra
