// The fading trail: thinned by distance, bounded memory, and a time window
// whose cost does not grow with the number of steps.
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>

#include "render/trail.hpp"

using vibra::render::Point;
using vibra::render::Trail;

namespace {
/// A circle of radius 1 traced for `turns` turns in `steps` steps.
Trail circle(long steps, double turns, size_t budget = size_t(1) << 16) {
  Trail trail(1e-3, budget);
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

namespace {
/// Distance from p to the segment a-b.
double to_segment(const Point& p, const Point& a, const Point& b) {
  const Point d = b - a;
  const double along = d.squaredNorm() > 0 ? std::clamp((p - a).dot(d) / d.squaredNorm(), 0.0, 1.0) : 0.0;
  return (p - (a + along * d)).norm();
}
}  // namespace

TEST_CASE("trail: the drawn path is within a quarter pixel of every kept point", "[render][trail]") {
  const Trail trail = circle(100000, 3);
  for (double zoom : {50.0, 200.0, 1000.0}) {
    const auto& drawn = trail.drawn_points(zoom);
    REQUIRE(drawn.size() >= 3);
    CHECK(drawn.front().t == trail.points().front().t);
    CHECK(drawn.back().t == trail.points().back().t);
    // Each kept point against the drawn segment spanning its time.
    size_t segment = 0;
    double worst = 0;
    for (const auto& k : trail.points()) {
      while (segment + 2 < drawn.size() && drawn[segment + 1].t < k.t) ++segment;
      worst = std::max(worst, to_segment(k.p, drawn[segment].p, drawn[segment + 1].p) * zoom);
    }
    CHECK(worst <= 0.25 + 1e-9);
    CHECK(worst > 0.05);  // the tolerance is used, not wasted on points it does not need
  }
}

TEST_CASE("trail: a frame draws as many points for a million steps as for a thousand", "[render][trail]") {
  // Five turns of a circle 200 pixels in radius: a segment of 20 pixels
  // misses the arc by a quarter pixel, so about 63 per turn, whatever the steps.
  const Trail coarse = circle(1000, 5), fine = circle(1000000, 5);
  const size_t few = coarse.drawn_points(200).size(), many = fine.drawn_points(200).size();
  CHECK(many <= 70 * 5);
  CHECK(few <= 70 * 5);
  CHECK(double(many) <= 1.1 * double(few));
  CHECK(double(few) <= 1.3 * double(many));
}

TEST_CASE("trail: memory stays within its budget over any number of steps", "[render][trail]") {
  for (long steps : {1000L, 100000L, 3000000L}) {
    const Trail trail = circle(steps, 100, 1024);
    CHECK(trail.points().size() <= 1024);
    CHECK(trail.drawn_points(200).size() <= trail.points().size());
  }
}
