// The fading trail: thinned by distance, bounded memory, and a time window
// whose cost does not grow with the number of steps.
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

#include "render/draw/canvas.hpp"
#include "render/draw/color.hpp"
#include "render/draw/polyline/trail.hpp"

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

namespace {
/// The canvas's pixel at (x, y), as 0xAARRGGBB.
std::uint32_t pixel_at(const vibra::render::Canvas& c, int x, int y) {
  return reinterpret_cast<const std::uint32_t*>(c.data() + y * c.stride())[x];
}

/// A straight trail along y = 0 from x = 0 to 10 over 10 time units.
Trail straight() {
  Trail trail(1e-3);
  for (int n = 0; n <= 1000; ++n) trail.add(n * 0.01, Point(n * 0.01, 0));
  return trail;
}
}  // namespace

TEST_CASE("trail: the fade darkens steadily toward the head, without beads where its steps meet",
          "[render][trail]") {
  using namespace vibra::render;
  Canvas canvas = Canvas::image(600, 100);
  canvas.clear(palette::paper);
  const WorldView view(Eigen::AlignedBox2d(Point(0, -1), Point(10, 1)), {50, 0, 500, 100});
  straight().draw(canvas, view, 10, 8, palette::ink, 2);
  canvas.flush();
  // Along the line's centre, from the tail end (x = 2) to the head (x = 10):
  // never lighter than the pixel before it.
  int previous = 256, steps = 0;
  for (int x = int(view.to_pixel(Point(2.3, 0)).x()); x < int(view.to_pixel(Point(9.9, 0)).x()); ++x) {
    const int green = int(pixel_at(canvas, x, 50) >> 8 & 0xff);
    INFO("x = " << x);
    REQUIRE(green <= previous);
    steps += green < previous;
    previous = green;
  }
  CHECK(steps >= 15);  // it fades in steps, not at once
}

TEST_CASE("trail: a frame's pixels depend only on its time, not on the frames drawn before", "[render][trail]") {
  using namespace vibra::render;
  const Trail trail = circle(20000, 4);
  const WorldView view(Eigen::AlignedBox2d(Point(-1.2, -1.2), Point(1.2, 1.2)), {0, 0, 300, 300});
  Canvas running = Canvas::image(300, 300);
  for (double t = 2; t < 25; t += 0.37) {
    running.clear(palette::paper);
    trail.draw(running, view, t, 6, palette::blue, 1.6, Point(std::cos(t), std::sin(t)));
    Canvas fresh = Canvas::image(300, 300);
    fresh.clear(palette::paper);
    circle(20000, 4).draw(fresh, view, t, 6, palette::blue, 1.6, Point(std::cos(t), std::sin(t)));
    running.flush(), fresh.flush();
    INFO("t = " << t);
    bool same = true;
    for (int y = 0; y < 300 && same; ++y)
      same = std::memcmp(running.data() + y * running.stride(), fresh.data() + y * fresh.stride(), 4 * 300) == 0;
    CHECK(same);
  }
}
