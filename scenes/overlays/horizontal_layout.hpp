// Where the parts of a horizontal spring-mass drawing go (Figs 1.17, 1.18): wall, floor and body.
#pragma once
#include <algorithm>
#include <cmath>
#include <utility>

#include "scenes/diagrams/diagram.hpp"

namespace vibra::scenes {

/// Where the parts of a horizontal spring-mass drawing go (Figs 1.17, 1.18):
/// a wall at x = 0, a floor at y = 0, and a body whose left face sits at
/// rest_length + u. Every length is a multiple of `unit`, the largest |u|
/// of the run, so the drawing fills the view whatever the amplitude.
struct HorizontalLayout {
  double unit = 1;
  double rest_length = 2.3, body_width = 1.4, body_height = 1.0, wheel_radius = 0.14, wall_height = 2.2;
  bool wheels = true;

  explicit HorizontalLayout(double largest_u, bool on_wheels) : wheels(on_wheels) {
    unit = largest_u > 0 && std::isfinite(largest_u) ? largest_u : 1;
    rest_length *= unit, body_width *= unit, body_height *= unit, wheel_radius *= unit, wall_height *= unit;
  }
  double body_bottom() const { return wheels ? 2 * wheel_radius : 0; }
  double body_left(double u) const { return rest_length + u; }
  Point body_center(double u) const { return {body_left(u) + 0.5 * body_width, body_bottom() + 0.5 * body_height}; }
  /// A height on the body as a fraction of its height (0 bottom, 1 top).
  double height_at(double fraction) const { return body_bottom() + fraction * body_height; }
  /// Equilibrium position of the body's centre line.
  double equilibrium_x() const { return rest_length + 0.5 * body_width; }
  /// The dimension line marking u above the body: from the equilibrium line
  /// to the body's centre line.
  std::pair<Point, Point> u_dimension(double u) const {
    const double y = body_bottom() + body_height + 0.35 * unit;
    return {Point(equilibrium_x(), y), Point(equilibrium_x() + u, y)};
  }
  /// Everything but the force arrows, for the world box.
  WorldBox extent() const {
    WorldBox box(Point(-0.35 * unit, -0.25 * unit),
                 Point(rest_length + unit + body_width + 0.2 * unit, body_bottom() + body_height + 0.75 * unit));
    box.extend(Point(0, wall_height));
    return box;
  }
};

}  // namespace vibra::scenes
