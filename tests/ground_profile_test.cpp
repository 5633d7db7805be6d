// The road's ground (draw_ground_profile): a hatched band under the profile,
// fixed to the world, so a view that follows a vehicle moves it as a whole.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <cstdlib>

#include "render/canvas.hpp"
#include "render/machine_elements.hpp"

using namespace vibra::render;

namespace {
constexpr int kWidth = 480, kHeight = 240;

std::uint32_t pixel(const Canvas& c, int x, int y) {
  return reinterpret_cast<const std::uint32_t*>(c.data() + y * c.stride())[x];
}

double road(double x) { return 0.4 * std::sin(1.3 * x); }

/// The ground over world x in [left, left + 12], y in [-2, 2].
Canvas ground(double left) {
  Canvas canvas = Canvas::image(kWidth, kHeight);
  canvas.clear(palette::paper);
  const WorldView view(Eigen::AlignedBox2d(Point(left, -2), Point(left + 12, 2)), {0, 0, kWidth, kHeight});
  draw_ground_profile(canvas, view, road, 0.05, 10, {palette::ink, 2});  // deeper than the view
  canvas.flush();
  return canvas;
}
}  // namespace

TEST_CASE("ground profile: moving the view by whole pixels moves the road and its hatches with it",
          "[render][road]") {
  const double zoom = kWidth / 12.0;
  const int shift = 37;  // pixels: not a whole number of hatch periods
  const Canvas a = ground(0.7), b = ground(0.7 + shift / zoom);
  int largest = 0;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 8; x + shift < kWidth - 8; ++x) {
      const std::uint32_t p = pixel(a, x + shift, y), q = pixel(b, x, y);
      for (int channel = 0; channel < 32; channel += 8)
        largest = std::max(largest, std::abs(int(p >> channel & 0xff) - int(q >> channel & 0xff)));
    }
  CHECK(largest <= 1);
}

TEST_CASE("ground profile: nothing above the road, the band below it hatched at a steady pitch", "[render][road]") {
  const Canvas c = ground(0);
  const WorldView view(Eigen::AlignedBox2d(Point(0, -2), Point(12, 2)), {0, 0, kWidth, kHeight});
  for (int x = 20; x < kWidth - 20; x += 23) {
    const double top = view.to_pixel(Point(x / (kWidth / 12.0), road(x / (kWidth / 12.0)))).y();
    for (int y = 0; y < int(top) - 4; ++y) REQUIRE(pixel(c, x, y) == 0xffffffffu);
    // Below the road's line: the pale band, crossed by darker hatches.
    int hatches = 0;
    bool on_hatch = false;
    for (int y = int(top) + 5; y < kHeight; ++y) {
      const int green = int(pixel(c, x, y) >> 8 & 0xff);
      REQUIRE(pixel(c, x, y) != 0xffffffffu);  // the pale fill everywhere in the band
      const bool dark = green < 200;
      if (dark && !on_hatch) ++hatches;
      on_hatch = dark;
    }
    const double period = 14 * c.scale(), depth = kHeight - (top + 5);
    CHECK(hatches >= int(depth / period) - 1);
    CHECK(hatches <= int(depth / period) + 2);
  }
}
