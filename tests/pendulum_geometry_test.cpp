// The free-body diagram's geometry is a pure function of the state (docs/drawing.md).
#include <catch2/catch.hpp>
#include <cmath>

#include "scenes/diagrams/pendulum_geometry.hpp"

using namespace vibra::scenes;

namespace {
void check_point(const Point& p, double x, double y) {
  CHECK(p.x() == Approx(x).margin(1e-12));
  CHECK(p.y() == Approx(y).margin(1e-12));
}
}  // namespace

TEST_CASE("hanging at rest: bob below the pivot, S = mg up, no drag", "[scene]") {
  const PendulumGeometry g = pendulum_geometry({0, 0, 0, 1, 0}, {});
  check_point(g.bob, 0, -1);
  check_point(g.gravity_tip, 0, -1.6);      // unit force is 1.2 L/2
  check_point(g.wire_force_tip, 0, -0.4);   // toward the pivot
  check_point(g.drag_tip, 0, -1);
  check_point(g.vertical_end, 0, -1.0 / 3);
  CHECK(g.arc_from == Approx(-M_PI / 2));
  CHECK(g.arc_to == Approx(-M_PI / 2));
}

TEST_CASE("at 90 degrees moving: wire horizontal, drag along i_theta magnified", "[scene]") {
  // theta = pi/2, omega = 1: S = omega^2 + cos(theta) = 1, D = -alpha |omega| omega = -0.4.
  const PendulumGeometry g = pendulum_geometry({0, M_PI / 2, 1, 1, -0.4}, {});
  check_point(g.bob, 1, 0);
  check_point(g.wire_force_tip, 1 - 0.6, 0);
  // i_theta = (cos theta, sin theta) = (0, 1); D < 0 points down, 5 times 0.6 * 0.4 long.
  check_point(g.drag_tip, 1, -5 * 0.6 * 0.4);
  check_point(g.gravity_tip, 1, -0.6);
  CHECK(g.arc_to == Approx(0));
  check_point(g.theta_label_direction, std::cos(-M_PI / 4), std::sin(-M_PI / 4));
}

TEST_CASE("at 30 degrees: positions and the angle arc", "[scene]") {
  PendulumDiagramOptions o;
  o.drag_magnification = 2;
  const double th = M_PI / 6;
  const PendulumGeometry g = pendulum_geometry({0, th, -0.5, 1.2, 0.1}, o);
  check_point(g.bob, 0.5, -std::cos(th));
  check_point(g.wire_force_tip, 0.5 * (1 - 0.72), -std::cos(th) * (1 - 0.72));
  check_point(g.drag_tip, 0.5 + 2 * 0.6 * 0.1 * std::cos(th), -std::cos(th) + 2 * 0.6 * 0.1 * std::sin(th));
  CHECK(g.arc_to - g.arc_from == Approx(th));
}
