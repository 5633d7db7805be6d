// Drawing options for the book's figures: `--annotate` (the staggered mesh of
// Fig 1.12 in vibra plot, the pendulum's geometry in render) with the refusals
// that send each annotation to the command that draws it, and `--exaggerate`.
#include <catch2/catch.hpp>
#include <cmath>

#include "cli_support.hpp"
#include "core/error.hpp"
#include "png_compare.hpp"
#include "render/plot/figure.hpp"
#include "scenes/overlays/annotations.hpp"
#include "scenes/figures/mesh_marks.hpp"
#include "test_support.hpp"

using namespace vibra;
using test::check_refused;
using test::colour_pixels;
using test::run_vibra;
using test::ScratchDirectory;

namespace {
/// The mesh marks of a whole run on u and v panels, fed its step rows.
std::vector<scenes::MeshMarks::Dots> mesh_dots(const std::vector<std::string>& settings) {
  auto run = test::trajectory("undamped", settings);
  render::Figure figure(1280, 720);
  scenes::MeshMarks marks(run->info(), 1280);
  marks.mark_panel(figure, figure.add_panel({"u", "t"}), 1, 1, render::palette::blue);
  marks.mark_panel(figure, figure.add_panel({"v", "t"}), 2, 1, render::palette::green);
  for (const auto& row : test::rows(*run)) marks.observe_step(row);
  return marks.dots();
}
}  // namespace

TEST_CASE("mesh: the staggered scheme's v sits at the half steps, with the values the scheme computes",
          "[annotate][schemes]") {
  const double w = 2 * M_PI, dt = 0.125, I = 0.7, V = 0.3;
  const auto dots = mesh_dots({"scheme=staggered", "dt=0.125", "T=2", "I=0.7", "V=0.3"});
  REQUIRE(dots.size() == 2);
  const auto& u = dots[0].points;
  const auto& v = dots[1].points;
  REQUIRE(u.size() == 17);
  REQUIRE(v.size() == 16);
  CHECK_FALSE(dots[0].half_steps);
  CHECK(dots[1].half_steps);
  // The staggered scheme by hand: v^{1/2} = V - dt/2 w^2 I, v^{n+1/2} = v^{n-1/2} - dt w^2 u^n.
  double half = V - 0.5 * dt * w * w * I, un = I;
  for (size_t n = 0; n < v.size(); ++n) {
    INFO("n = " << n);
    CHECK(u[n].first == Approx(n * dt).margin(1e-12));
    CHECK(u[n].second == Approx(un).margin(1e-12));
    CHECK(v[n].first == Approx((n + 0.5) * dt).margin(1e-12));
    CHECK(v[n].second == Approx(half).margin(1e-11));
    un += dt * half;
    half -= dt * w * w * un;
  }
}

TEST_CASE("mesh: other schemes keep v at the mesh points, as the rows give it", "[annotate][schemes]") {
  auto run = test::trajectory("undamped", {"scheme=rk4", "dt=0.1", "T=1"});
  const auto rows = test::rows(*run);
  const auto dots = mesh_dots({"scheme=rk4", "dt=0.1", "T=1"});
  REQUIRE(dots[1].points.size() == rows.size());
  CHECK_FALSE(dots[1].half_steps);
  for (size_t n = 0; n < rows.size(); ++n) {
    CHECK(dots[1].points[n].first == rows[n][0]);
    CHECK(dots[1].points[n].second == rows[n][2]);
  }
}

TEST_CASE("mesh: more steps than the picture can show apart are refused", "[annotate]") {
  auto run = test::trajectory("undamped", {"dt=0.01", "T=10"});
  CHECK_THROWS_WITH(scenes::MeshMarks(run->info(), 1280),
                    Catch::Contains("1000 steps do not fit 1280 pixels") && Catch::Contains("steps_per_period=8"));
  auto adaptive = test::trajectory("undamped", {"scheme=dopri5", "rtol=1e-12", "T=50"});
  scenes::MeshMarks marks(adaptive->info(), 640);
  CHECK_THROWS_AS(
      [&] {
        for (const auto& row : test::rows(*adaptive)) marks.observe_step(row);
      }(),
      UsageError);
}

TEST_CASE("vibra plot --annotate mesh draws the dots and each annotation is refused where it is not drawn", "[annotate]") {
  ScratchDirectory dir;
  const auto r = run_vibra(
      "plot undamped --set scheme=staggered --set steps_per_period=8 --set periods=2 --panels u,v --annotate mesh -o " +
      (dir / "mesh.png"));
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  CHECK(colour_pixels(dir / "mesh.png", render::palette::vermillion, 360, 720) > 300);  // the half-step dots
  check_refused("render pendulum --annotate mesh --at 1 -o OUT.png",
                "annotation 'mesh' is drawn by vibra plot, not vibra render");
  check_refused("plot undamped --annotate geometry -o OUT.png",
                "annotation 'geometry' is drawn by vibra render, not vibra plot");
  check_refused("render spring --annotate geometry --at 1 -o OUT.png",
                "drawn on the pendulum diagram, and this scene's is oscillator");
  check_refused("render pendulum --annotate geometry --layout plot --at 1 -o OUT.png",
                "--annotate geometry marks the diagram");
  check_refused("render pendulum --annotate geometr --at 1 -o OUT.png", "did you mean 'geometry'?");
  check_refused("plot undamped --annotate mesh -o OUT.png", "400 steps do not fit");
  check_refused("plot undamped --annotate mesh --compare dt=0.1,0.2 -o OUT.png", "drop --compare");
  check_refused("plot undamped --annotate mesh -o OUT.html", "a page's plots are zoomable");
}

TEST_CASE("exaggerate belongs to the bumpy road: refused elsewhere and below 1", "[annotate]") {
  check_refused("render pendulum --exaggerate 3 --at 1 -o OUT.png", "the pendulum diagram is drawn true to scale");
  check_refused("render bumpy_road --exaggerate 0.5 --at 1 -o OUT.png", "would shrink the motion");
  check_refused("render bumpy_road --exaggerate 1e5 --at 1 -o OUT.png", "exaggerate");
  ScratchDirectory dir;
  const auto r = run_vibra("render bumpy_road --exaggerate 10 --at 1 --size 640x360 -o " + (dir / "road.png"));
  INFO(r.err);
  CHECK(r.exit_code == 0);
}
