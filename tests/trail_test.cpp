// The fading trail: thinned by distance, bounded memory, and a time window
// whose cost does not grow with the number of steps.
#include <catch2/catch.hpp>
#include <cmath>

#include "render/trail.hpp"

using vibra::render::Point;
using vibra::render::Trail;

namespace {
/// A circle of radius 1 traced for `turns` turns in `steps` steps.
Trail circle(long steps, double turns) {
  Trail trail(1e-3);
  for (long n = 0; n <= steps; ++n) {
    const double t = 2 * M_PI * turns * n / steps;
    trail.add(t, Point(std::cos(t), std::sin(t)));
  }
  return trail;
}
}  // namespace

TEST_CASE("trail: points at least the spacing apart, in time order, on the path", "[render][trail]") {
  const Trail trail = circle(100000, 1);
  const auto& p = trail.points();
  REQUIRE(p.size() > 1000);
  for (size_t i = 1; i < p.size(); ++i) {
    CHECK(p[i].t > p[i - 1].t);
    CHECK((p[i].p - p[i - 1].p).norm() >= trail.spacing());
    CHECK(p[i].p.norm() == Approx(1).epsilon(1e-12));
  }
}

TEST_CASE("trail: a million steps keep no more points than a thousand per window, and memory is bounded",
          "[render][trail]") {
  // The same two turns per window, one run a thousand times finer in time.
  const Trail coarse = circle(1000, 100), fine = circle(1000000, 100);
  const double window = 4 * M_PI, end = 200 * M_PI;
  const size_t few = coarse.between(end - window, end).size(), many = fine.between(end - window, end).size();
  CHECK(many <= size_t(1) << 16);
  CHECK(fine.points().size() <= size_t(1) << 16);
  // The fine run keeps at most the points its spacing allows along two turns.
  CHECK(many <= 4 * M_PI / fine.spacing() + 2);
  CHECK(few <= many);
}
