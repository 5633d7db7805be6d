// The pendulum diagram's geometry at one instant, a pure function of the state (forces in units of m g).
#pragma once
#include <Eigen/Core>

namespace vibra::scenes {

using Point = Eigen::Vector2d;

/// What the free-body diagram shows at one instant, in scaled units (docs/models.md):
/// forces divided by m g.
struct PendulumState {
  double t = 0, theta = 0, omega = 0, S = 0, D = 0;
};

/// Proportions of the diagram (docs/drawing.md), in units of the wire length L = 1.
struct PendulumDiagramOptions {
  double force_unit = 0.6;          ///< arrow length per unit of scaled force (1.2 L/2)
  double drag_magnification = 5;    ///< D is drawn this many times longer, and labelled so
  double bob_radius = 1.0 / 12;     ///< L/12: a body a hall sees, with room for its forces' casings
  double arc_radius = 1.0 / 6;      ///< L/6
  double vertical_length = 1.0 / 3; ///< dashed reference line, L/3
  double unit_vector_length = 0.25; ///< i_r and i_theta as drawn by `--annotate geometry`
  /// `--annotate geometry` (Fig 1.21): the unit vectors i_r and i_theta, the
  /// pivot (x0, y0) and the wire's length L.
  bool geometry = false;
  /// Whether the swing can rise above the horizontal, where S < 0 and the
  /// link pushes: the S panel's title names a rod only then.
  bool link_may_push = true;
};

/// Every point of the diagram in world units, pivot at the origin, y up.
/// A pure function of the state: the drawing only strokes these.
struct PendulumGeometry {
  Point pivot, bob;
  Point gravity_tip, wire_force_tip, drag_tip;  ///< arrows start at the bob
  Point vertical_end;
  double arc_from = 0, arc_to = 0;  ///< world angles (radians ccw from +x) of the theta arc
  Point theta_label_direction;      ///< unit vector from the pivot through the arc's midpoint
  /// The unit vectors i_r (pivot to bob) and i_theta (increasing theta), drawn
  /// from the bob's far edge so that they stand clear of the force arrows,
  /// which start at its centre.
  Point unit_origin, radial_unit_tip, azimuthal_unit_tip;
};

PendulumGeometry pendulum_geometry(const PendulumState&, const PendulumDiagramOptions&);

}  // namespace vibra::scenes
