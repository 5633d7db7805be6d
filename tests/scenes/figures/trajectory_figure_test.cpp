// vibra plot's figures of one run: the phase plane and the path at one scale in x and y, so a circle is round.
#include <cairo.h>

#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>

#include "cli_support.hpp"
#include "render/draw/color.hpp"
#include "scenes/figures/trajectory_figure.hpp"
#include "test_support.hpp"

using namespace vibra;
using vibra::test::ScratchDirectory;

namespace {
/// The width over the height of the pixels of one colour in a PNG.
double aspect_of(const std::filesystem::path& png, const render::Color& c) {
  cairo_surface_t* picture = cairo_image_surface_create_from_png(png.c_str());
  REQUIRE(cairo_surface_status(picture) == CAIRO_STATUS_SUCCESS);
  const unsigned char* data = cairo_image_surface_get_data(picture);
  const int stride = cairo_image_surface_get_stride(picture);
  int x0 = 1 << 30, x1 = -1, y0 = 1 << 30, y1 = -1;
  for (int y = 0; y < cairo_image_surface_get_height(picture); ++y)
    for (int x = 0; x < cairo_image_surface_get_width(picture); ++x) {
      const unsigned char* p = data + y * stride + 4 * x;  // B, G, R, A
      if (std::abs(p[2] - c.r * 255) < 30 && std::abs(p[1] - c.g * 255) < 30 && std::abs(p[0] - c.b * 255) < 30)
        x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
    }
  cairo_surface_destroy(picture);
  REQUIRE(x1 > x0);
  return double(x1 - x0) / (y1 - y0);
}
}  // namespace

TEST_CASE("plot's phase plane and path draw one unit as long across as up: the circles are round", "[figure]") {
  ScratchDirectory dir;
  // The undamped spring's (u, v/w) and the circular orbit's (x, y) are circles.
  struct Case {
    const char* model;
    const char* panel;
  };
  for (const Case c : {Case{"undamped", "phase"}, Case{"two-body", "path"}}) {
    INFO(c.model << " " << c.panel);
    auto run = test::trajectory(c.model, {"scheme=rk4", "steps_per_period=400", "periods=1"});
    const auto png = dir.path / (std::string(c.panel) + ".png");
    scenes::trajectory_figure(*run, {c.panel}, 1200, 500, "").write(png);
    CHECK(aspect_of(png, render::palette::blue) == Approx(1).epsilon(0.03));
  }
}
