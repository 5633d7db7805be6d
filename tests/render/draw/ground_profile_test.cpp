// The road's ground (GroundProfile): a hatched band under the profile, fixed
// to the world, so a view that follows a vehicle moves it as a whole; pasted
// from tiles on an image canvas, drawn as it is on a vector one.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <cstdlib>

#include "render/draw/canvas.hpp"
#include "render/draw/elements/ground_profile.hpp"

using namespace vibra::render;

namespace {
constexpr int kGroundWidth = 480, kGroundHeight = 240;

std::uint32_t pixel(const Canvas& c, int x, int y) {
  return reinterpret_cast<const std::uint32_t*>(c.data() + y * c.stride())[x];
}

double road(double x) { return 0.4 * std::sin(1.3 * x); }

/// The ground over world x in [left, left + 12], y in [-2, 2].
Canvas ground(double left) {
  Canvas canvas = Canvas::image(kGroundWidth, kGroundHeight);
  canvas.clear(palette::paper);
  const WorldView view(Eigen::AlignedBox2d(Point(left, -2), Point(left + 12, 2)), {0, 0, kGroundWidth, kGroundHeight});
  GroundProfile(road, 0.05, 10, {palette::ink, 2}).draw(canvas, view);  // deeper than the view
  canvas.flush();
  return canvas;
}
}  // namespace

TEST_CASE("ground profile: moving the view by whole pixels moves the road and its hatches with it",
          "[render][road]") {
  const double zoom = kGroundWidth / 12.0;
  const int shift = 37;  // pixels: not a whole number of hatch periods
  const Canvas a = ground(0.7), b = ground(0.7 + shift / zoom);
  int largest = 0;
  for (int y = 0; y < kGroundHeight; ++y)
    for (int x = 8; x + shift < kGroundWidth - 8; ++x) {
      const std::uint32_t p = pixel(a, x + shift, y), q = pixel(b, x, y);
      for (int channel = 0; channel < 32; channel += 8)
        largest = std::max(largest, std::abs(int(p >> channel & 0xff) - int(q >> channel & 0xff)));
    }
  CHECK(largest <= 1);
}

TEST_CASE("ground profile: nothing above the road, the band below it hatched at a steady pitch", "[render][road]") {
  const Canvas c = ground(0);
  const WorldView view(Eigen::AlignedBox2d(Point(0, -2), Point(12, 2)), {0, 0, kGroundWidth, kGroundHeight});
  for (int x = 20; x < kGroundWidth - 20; x += 23) {
    const double top = view.to_pixel(Point(x / (kGroundWidth / 12.0), road(x / (kGroundWidth / 12.0)))).y();
    for (int y = 0; y < int(top) - 4; ++y) REQUIRE(pixel(c, x, y) == 0xffffffffu);
    // Below the road's line: the pale band, crossed by darker hatches.
    int hatches = 0;
    bool on_hatch = false;
    for (int y = int(top) + 5; y < kGroundHeight; ++y) {
      const int green = int(pixel(c, x, y) >> 8 & 0xff);
      REQUIRE(pixel(c, x, y) != 0xffffffffu);  // the pale fill everywhere in the band
      const bool dark = green < 200;
      if (dark && !on_hatch) ++hatches;
      on_hatch = dark;
    }
    const double period = 14 * c.scale(), depth = kGroundHeight - (top + 5);
    CHECK(hatches >= int(depth / period) - 1);
    CHECK(hatches <= int(depth / period) + 2);
  }
}

TEST_CASE("ground profile: tiles kept over a drive give each frame the pixels of a first drawing", "[render][road]") {
  // A view following a vehicle at a speed that is not a whole number of
  // pixels a frame: tiles are made, pasted, and dropped behind it.
  const GroundProfile kept(road, 0.05, 10, {palette::ink, 2});
  Canvas running = Canvas::image(kGroundWidth, kGroundHeight);
  for (int frame = 0; frame < 40; ++frame) {
    const double left = 0.3 + frame * 0.737;
    const WorldView view(Eigen::AlignedBox2d(Point(left, -2), Point(left + 12, 2)), {0, 0, kGroundWidth, kGroundHeight});
    running.clear(palette::paper);
    kept.draw(running, view);
    running.flush();
    const Canvas fresh = ground(left);
    INFO("frame " << frame);
    bool same = true;
    for (int y = 0; y < kGroundHeight && same; ++y)
      for (int x = 0; x < kGroundWidth && same; ++x) same = pixel(running, x, y) == pixel(fresh, x, y);
    CHECK(same);
  }
}
