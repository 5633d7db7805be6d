// vibra plot's figures of one run: the phase plane and the path at one scale in x and y, so a circle is round.
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>

#include "cli_support.hpp"
#include "png_compare.hpp"
#include "render/draw/color.hpp"
#include "scenes/figures/trajectory_figure.hpp"
#include "test_support.hpp"

using namespace vibra;
using vibra::test::ScratchDirectory;

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
    CHECK(test::colour_aspect(png, render::palette::blue) == Approx(1).epsilon(0.03));
  }
}
