// What the pendulum's picture is drawn with, checked by name where a golden hash would only trip: the wire, the
// dashed vertical, the angle's arc and the bob in the style table's colours, widths and dash, at the sizes the
// wire's length sets; each panel's curve and the force key in their forces' colours.
//
// Read from an SVG still (Cairo writes each stroke with its colour, width,
// opacity and dash). The shapes are found by geometry, never by the property
// under test: the bob is the one shape both filled and outlined with curves,
// the wire the straight stroke that ends at its centre, and so on.
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "cli_support.hpp"
#include "scenes/config/scene_config.hpp"
#include "svg_shapes.hpp"

using vibra::test::same_colour;
using vibra::test::SvgShape;

namespace {

struct Spot {
  double x = 0, y = 0;
};

double distance(Spot a, Spot b) { return std::hypot(a.x - b.x, a.y - b.y); }

Spot first(const SvgShape& s) { return {s.x(0), s.y(0)}; }
Spot last(const SvgShape& s) { return {s.x(s.points() - 1), s.y(s.points() - 1)}; }

/// The centre and radius of a circle drawn as Bézier curves: half its box.
std::pair<Spot, double> circle_of(const SvgShape& s) {
  double x0 = 1e9, y0 = 1e9, x1 = -1e9, y1 = -1e9;
  for (size_t i = 0; i < s.points(); ++i)
    x0 = std::min(x0, s.x(i)), x1 = std::max(x1, s.x(i)), y0 = std::min(y0, s.y(i)), y1 = std::max(y1, s.y(i));
  return {{(x0 + x1) / 2, (y0 + y1) / 2}, (x1 - x0) / 2};
}

/// The pendulum's own shapes, found by where they are.
struct PendulumShapes {
  const SvgShape *bob = nullptr, *wire = nullptr, *vertical = nullptr, *arc = nullptr;
  Spot pivot, centre;
  double length = 0;  ///< the wire's, in pixels: the diagram's sizes are fractions of it
};

PendulumShapes find_pendulum(const std::vector<SvgShape>& shapes) {
  PendulumShapes p;
  for (const auto& s : shapes)
    if (s.curved && !s.fill.empty() && !s.stroke.empty()) {
      CHECK(p.bob == nullptr);  // one shape filled and outlined with curves: the bob
      p.bob = &s;
    }
  REQUIRE(p.bob);
  p.centre = circle_of(*p.bob).first;
  for (const auto& s : shapes)
    if (!s.curved && s.points() == 2 && distance(last(s), p.centre) < 0.01) p.wire = &s;
  REQUIRE(p.wire);  // a straight stroke from the pivot to the bob's centre
  p.pivot = first(*p.wire);
  p.length = distance(p.pivot, p.centre);
  for (const auto& s : shapes) {
    if (!s.curved && s.points() == 2 && distance(first(s), p.pivot) < 0.01 && std::abs(s.x(1) - p.pivot.x) < 0.01 &&
        s.y(1) > p.pivot.y)
      p.vertical = &s;  // straight down from the pivot
    if (s.curved && s.fill.empty() && std::abs(distance(first(s), p.pivot) - p.length / 6) < 0.5) p.arc = &s;
  }
  REQUIRE(p.vertical);
  REQUIRE(p.arc);
  return p;
}

std::vector<SvgShape> still(const std::string& layout) {
  vibra::test::ScratchDirectory dir;
  const auto r = vibra::test::run_vibra("render pendulum --at 1 -q --layout " + layout + " -o " + (dir / "x.svg"));
  REQUIRE(r.exit_code == 0);
  return vibra::test::svg_shapes(vibra::test::read_file(dir / "x.svg"));
}

}  // namespace

TEST_CASE("the pendulum's wire, dashed vertical, angle arc and bob: the style table's colours, widths and dash",
          "[scene][diagram][drawing]") {
  const auto colors = vibra::scenes::load_scene("pendulum").colors;
  const auto shapes = still("fbd");
  const PendulumShapes p = find_pendulum(shapes);
  INFO("pivot (" << p.pivot.x << ", " << p.pivot.y << "), bob at (" << p.centre.x << ", " << p.centre.y << ")");
  REQUIRE(p.length > 100);
  SECTION("the wire: solid, 2.2 wide, in the wire's colour") {
    CHECK(same_colour(p.wire->stroke, colors.wire));
    CHECK(p.wire->width == Approx(2.2));
    CHECK(p.wire->stroke_opacity == 1);
    CHECK(p.wire->dasharray.empty());
  }
  SECTION("the vertical: L/3 long, 1.6 wide, dashed 4 widths on and 3 off, the wire's colour at 0.6") {
    CHECK(distance(first(*p.vertical), last(*p.vertical)) == Approx(p.length / 3).epsilon(1e-3));
    CHECK(same_colour(p.vertical->stroke, colors.wire));
    CHECK(p.vertical->stroke_opacity == Approx(0.6));
    CHECK(p.vertical->width == Approx(1.6));
    CHECK(p.vertical->dasharray == "6.4,4.8");
  }
  SECTION("the angle's arc: radius L/6 from the vertical to the wire, 1.6 wide, in the wire's colour") {
    const Spot down{p.pivot.x, p.pivot.y + p.length / 6};
    const Spot on_wire{p.pivot.x + (p.centre.x - p.pivot.x) / 6, p.pivot.y + (p.centre.y - p.pivot.y) / 6};
    CHECK(distance(first(*p.arc), down) < 0.01);
    CHECK(distance(last(*p.arc), on_wire) < 0.01);
    CHECK(same_colour(p.arc->stroke, colors.wire));
    CHECK(p.arc->width == Approx(1.6));
  }
  SECTION("the bob: radius L/12, filled in the bob's colour, outlined 1.6 wide in the wire's") {
    CHECK(circle_of(*p.bob).second == Approx(p.length / 12).epsilon(1e-3));
    CHECK(same_colour(p.bob->fill, colors.bob));
    CHECK(same_colour(p.bob->stroke, colors.wire));
    CHECK(p.bob->width == Approx(1.6));
  }
}

TEST_CASE("the pendulum's panels draw theta, S and D in the bob's, the wire force's and the drag's colours, "
          "and the force key names mg, S and D in their arrows' colours",
          "[scene][diagram][drawing]") {
  const auto colors = vibra::scenes::load_scene("pendulum").colors;
  const auto shapes = still("fbd+plot");
  const PendulumShapes p = find_pendulum(shapes);
  // A panel's curve: a polyline of ten points or more right of the diagram (grid lines have two).
  std::vector<const SvgShape*> curves;
  for (const auto& s : shapes)
    if (!s.curved && s.points() >= 10 && s.fill.empty() && s.x(0) > p.centre.x + p.length) curves.push_back(&s);
  REQUIRE(curves.size() == 3);  // top to bottom, as the panels are drawn
  const vibra::render::Color expected[] = {colors.bob, colors.wire_force, colors.drag};
  const char* names[] = {"theta", "S", "D"};
  for (int i = 0; i < 3; ++i) {
    INFO("the panel of " << names[i] << ", drawn in " << curves[i]->stroke);
    CHECK(same_colour(curves[i]->stroke, expected[i]));
    CHECK(curves[i]->width == Approx(2.4));
    if (i) CHECK(curves[i]->y(0) > curves[i - 1]->y(0));
  }
  // The key's rows: short horizontal arrows under the diagram, one a force, in the order mg, S, D.
  std::vector<const SvgShape*> rows;
  for (const auto& s : shapes)
    if (!s.curved && s.points() == 2 && s.y(0) == s.y(1) && s.y(0) > p.centre.y + p.length / 12 &&
        s.x(1) - s.x(0) > 5 && s.x(1) - s.x(0) < 20)
      rows.push_back(&s);
  REQUIRE(rows.size() == 3);
  const vibra::render::Color forces[] = {colors.gravity, colors.wire_force, colors.drag};
  const char* force_names[] = {"mg", "S", "D"};
  for (int i = 0; i < 3; ++i) {
    INFO("the key's row of " << force_names[i] << ", drawn in " << rows[i]->stroke);
    CHECK(same_colour(rows[i]->stroke, forces[i]));
  }
}
