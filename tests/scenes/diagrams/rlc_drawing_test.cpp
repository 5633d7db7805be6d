// What the RLC circuit's picture shows, read from SVG stills: the capacitor's positive plate (tinted in the
// charge's colour) on the side the charge q says, at times of either sign, as drawn, not as computed.
#include <catch2/catch.hpp>
#include <cmath>
#include <string>
#include <vector>

#include "cli_support.hpp"
#include "scenes/config/scene_config.hpp"
#include "svg_shapes.hpp"

using vibra::test::same_colour;
using vibra::test::SvgShape;

namespace {
std::vector<SvgShape> still_at(double t) {
  vibra::test::ScratchDirectory dir;
  const auto r = vibra::test::run_vibra("render rlc --at " + std::to_string(t) + " -q --layout fbd -o " + (dir / "x.svg"));
  REQUIRE(r.exit_code == 0);
  return vibra::test::svg_shapes(vibra::test::read_file(dir / "x.svg"));
}

/// The x of the thick upright plate stroked in `colour` (NAN when there is none).
double plate_x(const std::vector<SvgShape>& shapes, const vibra::render::Color& colour) {
  double x = NAN;
  for (const SvgShape& s : shapes)
    if (!s.curved && s.points() == 2 && std::abs(s.x(0) - s.x(1)) < 0.01 && s.width > 4 && same_colour(s.stroke, colour)) {
      CHECK(std::isnan(x));  // one plate of each sign
      x = s.x(0);
    }
  return x;
}
}  // namespace

TEST_CASE("rlc picture: the plate tinted positive is the right one while q > 0, the left one while q < 0",
          "[scene][diagram][drawing]") {
  // The built-in scene, driven by V = 0.5 sin(1.2 t) from q = 0: q = 0.82 at
  // t = 8.5 and -0.86 at t = 11 (vibra solve of its settings).
  const auto colors = vibra::scenes::load_scene("rlc").colors;
  for (const auto& [t, sign] : {std::pair{8.5, 1}, std::pair{11.0, -1}}) {
    INFO("t = " << t);
    const auto shapes = still_at(t);
    const double positive = plate_x(shapes, colors.gravity), negative = plate_x(shapes, colors.bob);
    REQUIRE(std::isfinite(positive));
    REQUIRE(std::isfinite(negative));
    CHECK((positive - negative) * sign > 10);  // pixels apart, the gap between the plates
  }
}
