// A planar body's position and velocity from a row t, x, y, vx, vy (the elastic pendulum's, the orbit's).
#pragma once
#include <span>

#include "scenes/diagrams/diagram.hpp"

namespace vibra::scenes {

inline Point planar_position(std::span<const double> row) { return Point(row[1], row[2]); }
inline Point planar_velocity(std::span<const double> row) { return Point(row[3], row[4]); }

}  // namespace vibra::scenes
