// Where a label goes beyond a point (render/draw/text.hpp): its box's near edge `gap` away along the direction,
// and the ray form the label placer uses at many gaps the same to the bit.
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <random>

#include "render/draw/text.hpp"

using vibra::render::label_beyond;
using vibra::render::label_ray;
using vibra::render::Point;

TEST_CASE("a label beyond a point: the box's edge gap away along the direction, its centre on that line",
          "[render][labels]") {
  std::mt19937 random(13);
  std::uniform_real_distribution<double> coordinate(-500, 500), extent(1, 200), gap(0, 60), angle(-M_PI, M_PI);
  for (int trial = 0; trial < 2000; ++trial) {
    const Point tip(coordinate(random), coordinate(random)), size(extent(random), extent(random));
    const double a = trial % 8 == 0 ? (trial % 16) * M_PI / 4 : angle(random);  // the axes and diagonals too
    const double length = 0.1 + 10 * (trial % 5);  // any length: only the direction counts
    const Point direction = length * Point(std::cos(a), std::sin(a)), unit = direction / direction.norm();
    const double g = gap(random);
    const Point centre = label_beyond(tip, direction, size, g);
    INFO("trial " << trial);
    // The centre lies on the ray from the tip.
    const Point to_centre = centre - tip;
    CHECK(std::abs(to_centre.x() * unit.y() - to_centre.y() * unit.x()) < 1e-9 * (1 + to_centre.norm()));
    CHECK(to_centre.dot(unit) > 0);
    // The point gap along the ray is on the box's edge: the box touches it and does not cover the tip.
    const Point near = tip + g * unit;
    const double edge = std::max(std::abs(near.x() - centre.x()) / (0.5 * size.x()),
                                 std::abs(near.y() - centre.y()) / (0.5 * size.y()));
    CHECK(edge == Approx(1).epsilon(1e-9));
    // The placer's form: the same numbers to the last bit, at every gap.
    const auto ray = label_ray(direction, size);
    for (const double other : {0.0, g, 2 * g + 3})
      REQUIRE((label_beyond(tip, ray, other) - label_beyond(tip, direction, size, other)).norm() == 0);
  }
}
