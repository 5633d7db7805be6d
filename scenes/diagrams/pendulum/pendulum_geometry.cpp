// The pendulum diagram's geometry at one instant, a pure function of the state (forces in units of m g).
#include "scenes/diagrams/pendulum/pendulum_geometry.hpp"

#include <cmath>

namespace vibra::scenes {

PendulumGeometry pendulum_geometry(const PendulumState& s, const PendulumDiagramOptions& o) {
  PendulumGeometry g;
  const Point radial(std::sin(s.theta), -std::cos(s.theta));   // i_r: pivot to bob
  const Point azimuthal(std::cos(s.theta), std::sin(s.theta)); // i_theta: direction of increasing theta
  g.pivot = Point::Zero();
  g.bob = radial;
  g.gravity_tip = g.bob + Point(0, -o.force_unit);              // m g = 1 in scaled units
  g.wire_force_tip = g.bob - o.force_unit * s.S * radial;       // S pulls toward the pivot
  g.drag_tip = g.bob + o.force_unit * o.drag_magnification * s.D * azimuthal;
  g.vertical_end = Point(0, -o.vertical_length);
  // The arc sweeps from the downward vertical (-pi/2) to the wire.
  g.arc_from = -M_PI / 2;
  g.arc_to = -M_PI / 2 + s.theta;
  const double middle = -M_PI / 2 + s.theta / 2;
  g.theta_label_direction = Point(std::cos(middle), std::sin(middle));
  g.unit_origin = g.bob + o.bob_radius * radial;
  g.radial_unit_tip = g.unit_origin + o.unit_vector_length * radial;
  g.azimuthal_unit_tip = g.unit_origin + o.unit_vector_length * azimuthal;
  return g;
}

}  // namespace vibra::scenes
