// The free-body diagram's geometry is a pure function of the state (docs/drawing.md).
#include <catch2/catch.hpp>
#include <cmath>

#include "scenes/diagrams/pendulum/pendulum_geometry.hpp"

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

TEST_CASE("the unit vectors of Fig 1.21: i_r along the wire outwards, i_theta a quarter turn on, from the bob's edge",
          "[scene]") {
  for (double th : {-2.5, -0.4, 0.0, 0.7, 3.0}) {
    INFO("theta = " << th);
    const PendulumDiagramOptions o;
    const PendulumGeometry g = pendulum_geometry({0, th, 0.3, 1, 0}, o);
    // The book's i_r = sin(theta) i - cos(theta) j and i_theta = cos(theta) i + sin(theta) j.
    check_point(g.unit_origin, (1 + o.bob_radius) * std::sin(th), -(1 + o.bob_radius) * std::cos(th));
    check_point(g.radial_unit_tip - g.unit_origin, o.unit_vector_length * std::sin(th),
                -o.unit_vector_length * std::cos(th));
    check_point(g.azimuthal_unit_tip - g.unit_origin, o.unit_vector_length * std::cos(th),
                o.unit_vector_length * std::sin(th));
    // i_theta is where the bob goes as theta grows: the bob's position's derivative.
    const double h = 1e-6;
    const Point ahead = pendulum_geometry({0, th + h, 0.3, 1, 0}, o).bob;
    const Point velocity = (ahead - g.bob) / h;
    CHECK(velocity.dot(g.azimuthal_unit_tip - g.unit_origin) == Approx(o.unit_vector_length).epsilon(1e-5));
  }
}
