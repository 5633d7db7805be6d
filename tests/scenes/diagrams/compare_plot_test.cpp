// `vibra plot --compare KEY=V1,V2,...`: one curve per member in its own
// colour, the exact solution dashed, blow-ups marked, bad input refused.

#include <catch2/catch.hpp>
#include <cmath>
#include <memory>

#include "cli_support.hpp"
#include "png_compare.hpp"
#include "core/comparison.hpp"
#include "render/draw/color.hpp"
#include "scenes/diagrams/comparison_labels.hpp"
#include "scenes/figures/comparison_figure.hpp"
#include "test_support.hpp"

using namespace vibra;
using test::colour_pixels;
using test::run_vibra;
using test::ScratchDirectory;

TEST_CASE("plot --compare draws every member in its own palette colour", "[compare]") {
  ScratchDirectory dir;
  const auto r = run_vibra("plot undamped --compare scheme=forward-euler,backward-euler,crank-nicolson,rk4 "
                           "--set steps_per_period=20 --set periods=3 -o " + (dir / "c.png"));
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  CHECK(r.err == "vibra: wrote " + (dir / "c.png") + "\n");  // as every command that writes a file
  for (size_t m = 0; m < 4; ++m) {
    INFO("member " << m);
    CHECK(colour_pixels(dir / "c.png", render::palette::series(m)) > 400);
  }
}

TEST_CASE("plot --compare with one value draws that one run, in the first colour", "[compare]") {
  // A comparison of one member is allowed (a figure in the comparison's style
  // for one dt): nothing may assume a second member.
  ScratchDirectory dir;
  const auto r = run_vibra("plot undamped --compare dt=0.1 --set periods=3 -o " + (dir / "one.png"));
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  CHECK(r.err == "vibra: wrote " + (dir / "one.png") + "\n");
  CHECK(colour_pixels(dir / "one.png", render::palette::series(0)) > 400);
  CHECK(colour_pixels(dir / "one.png", render::palette::series(1)) == 0);
}

TEST_CASE("a member that leaves the view is marked and the others run to the end", "[compare]") {
  Comparison c(find_model("undamped"), model_settings("undamped", {"steps_per_period=20", "periods=8"}),
               parse_comparison("scheme=forward-euler,rk4"));
  scenes::comparison_figure(c, {"u", "phase"}, 800, 600, "");
  REQUIRE(c.blew_up(0));  // |u| beyond twice the bound I: by t = 1 (comparison_test.cpp)
  CHECK(c.blow_up_time(0) <= 1.05);
  CHECK_FALSE(c.blew_up(1));
  CHECK(c.trajectory(1).done());
  CHECK(scenes::comparison_caption("undamped", c) == "Δ<i>t</i> = 0.05 · comparing scheme");
}

TEST_CASE("a comparison's exact phase curve is the undamped circle u^2 + (v/w)^2 = I^2", "[compare]") {
  // u = I cos(w t), v = -I w sin(w t): in the phase panel's (u, v/w) a circle of radius I.
  Comparison c(find_model("undamped"), model_settings("undamped", {"I=1.5", "steps_per_period=20", "periods=2"}),
               parse_comparison("scheme=centered,rk4"));
  const render::Figure figure = scenes::comparison_figure(c, {"u", "phase"}, 800, 600, "");
  int exact_curves = 0;
  for (const auto& series : figure.series_of(1)) {
    if (!series->style().dashed || series->kind() != render::Series::Kind::path) continue;
    ++exact_curves;
    int points = 0;
    series->for_each_point([&](double u, double v_over_w) {
      ++points;
      CHECK(std::hypot(u, v_over_w) == Approx(1.5).epsilon(1e-6));
    });
    CHECK(points > 100);
  }
  CHECK(exact_curves == 1);
}

TEST_CASE("plot --compare refuses bad input with one line, exit code 2 and no file", "[compare]") {
  const std::pair<const char*, const char*> cases[] = {
      {"plot undamped --compare dt=0.1,0.05 --set dt=0.2 -o OUT.png", "dt is given both in --set and in --compare"},
      {"plot undamped --compare scheme=rk4,rk4 -o OUT.png", "given twice"},
      {"plot undamped --compare dt=0.1 --compare scheme=rk4 -o OUT.png", "one key at a time"},
      {"plot pendulum --compare Thta=10,20 -o OUT.png", "did you mean 'Theta'"},
      {"plot undamped --compare dt=1,2,3,4,5,6,7,8,9 -o OUT.png", "at most 8"},
      {"plot undamped --compare dt=0.1,,0.2 -o OUT.png", "empty value"},
      {"plot undamped --compare dt -o OUT.png", "not KEY=V1,V2"},
      {"plot undamped --compare scheme=rk4,rk9 -o OUT.png", "not a valid scheme"},
      {"plot undamped --compare dt=0.1,0.05 --panels u,phse -o OUT.png", "did you mean 'phase'"},
  };
  for (const auto& [args, expected] : cases) vibra::test::check_refused(args, expected);
}

TEST_CASE("a compared angle is named in degrees, or in radians when given so, other keys as given", "[compare]") {
  Comparison angles(find_model("pendulum"), model_settings("pendulum", {"periods=1"}), parse_comparison("Theta=30,60,1rad"));
  CHECK(scenes::member_markup(angles, 0) == "Theta = 30°");
  CHECK(scenes::member_markup(angles, 1) == "Theta = 60°");
  CHECK(scenes::member_markup(angles, 2) == "Theta = 1rad");
  Comparison drags(find_model("pendulum"), model_settings("pendulum", {"periods=1"}), parse_comparison("alpha=0.1,0.4"));
  CHECK(scenes::member_markup(drags, 1) == "alpha = 0.4");
  Comparison steps(find_model("undamped"), model_settings("undamped", {"periods=1"}), parse_comparison("dt=0.1,0.05"));
  CHECK(scenes::member_markup(steps, 0) == "Δ<i>t</i> = 0.1");
  Comparison schemes(find_model("undamped"), model_settings("undamped", {"periods=1"}), parse_comparison("scheme=rk4,centered"));
  CHECK(scenes::member_markup(schemes, 1) == "centered");
}

TEST_CASE("a comparison's caption states what the members share and not what they vary", "[compare]") {
  // Each member's dt differs: no dt in the caption, the shared scheme named.
  Comparison steps(find_model("undamped"), model_settings("undamped", {"scheme=rk4", "periods=1"}), parse_comparison("dt=0.1,0.05"));
  CHECK(scenes::comparison_caption("undamped", steps) == "rk4 · comparing Δ<i>t</i>");
  // The schemes differ: the shared dt, no scheme.
  Comparison schemes(find_model("undamped"), model_settings("undamped", {"dt=0.05", "periods=1"}),
                     parse_comparison("scheme=rk4,centered"));
  CHECK(scenes::comparison_caption("undamped", schemes) == "Δ<i>t</i> = 0.05 · comparing scheme");
}
