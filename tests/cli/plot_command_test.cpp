// `vibra plot`: panel names, defaults, and the figure the executable writes.

#include <catch2/catch.hpp>
#include <memory>

#include "cli_support.hpp"
#include "png_compare.hpp"
#include "core/error.hpp"
#include "render/draw/color.hpp"
#include "scenes/figures/trajectory_figure.hpp"
#include "test_support.hpp"

using namespace vibra;
using test::colour_pixels;
using test::png_size;
using test::run_vibra;
using test::ScratchDirectory;

namespace {
using Names = std::vector<std::string>;

Names defaults_for(const std::string& model) {
  return scenes::default_plot_panels(test::trajectory(model, {})->info());
}
}  // namespace

TEST_CASE("plot panels default to the chapter's figures for each model", "[plot]") {
  CHECK(defaults_for("pendulum") == Names{"theta", "S", "D"});
  CHECK(defaults_for("physical-pendulum") == Names{"theta", "S", "D"});
  CHECK(defaults_for("undamped") == Names{"u"});
  CHECK(defaults_for("vibration") == Names{"u"});
  CHECK(defaults_for("elastic-pendulum") == Names{"path"});
  CHECK(defaults_for("two-body") == Names{"path"});
  CHECK(scenes::plot_panel_names(test::trajectory("undamped", {})->info()) == Names{"u", "v", "exact", "phase"});
  CHECK(scenes::plot_panel_names(test::trajectory("sliding-box", {})->info()) ==
        Names{"u", "v", "exact", "phase", "friction"});
}

TEST_CASE("plot refuses unknown panels and an exact solution that does not exist", "[plot]") {
  auto undamped = test::trajectory("undamped", {});
  CHECK_THROWS_WITH(scenes::trajectory_figure(*undamped, {"u", "thta"}, 800, 600, ""),
                    Catch::Contains("unknown panel 'thta'") && Catch::Contains("choose from u, v, exact, phase"));
  CHECK_THROWS_WITH(scenes::trajectory_figure(*undamped, {"path"}, 800, 600, ""), Catch::Contains("unknown panel 'path'"));
  auto damped = test::trajectory("pendulum", {"alpha=0.4"});
  CHECK_THROWS_AS(scenes::trajectory_figure(*damped, {"theta", "exact"}, 800, 600, ""), UsageError);
  auto endless = test::trajectory("undamped", {"T=inf"});
  CHECK_THROWS_WITH(scenes::trajectory_figure(*endless, {"u"}, 800, 600, ""), Catch::Contains("finite end time"));
}

TEST_CASE("vibra plot stacks the pendulum's theta, S and D with data in each panel", "[plot]") {
  ScratchDirectory dir;
  const auto r = run_vibra("plot pendulum --size 1000x900 -o " + (dir / "p.png"));
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  CHECK(png_size(dir / "p.png") == std::make_pair(1000, 900));
  // Panel colours in turn: blue, green, purple; each appears in its third only.
  CHECK(colour_pixels(dir / "p.png", render::palette::blue, 0, 300) > 300);
  CHECK(colour_pixels(dir / "p.png", render::palette::green, 300, 600) > 300);
  CHECK(colour_pixels(dir / "p.png", render::palette::purple, 600, 900) > 300);
  CHECK(colour_pixels(dir / "p.png", render::palette::blue, 300, 900) == 0);
}

TEST_CASE("vibra plot overlays the exact solution dashed and writes vector formats", "[plot]") {
  ScratchDirectory dir;
  REQUIRE(run_vibra("plot undamped --panels u,exact --set periods=3 -o " + (dir / "u.png")).exit_code == 0);
  CHECK(png_size(dir / "u.png") == std::make_pair(1280, 720));
  CHECK(colour_pixels(dir / "u.png", render::palette::vermillion, 0, 720) > 300);
  REQUIRE(run_vibra("plot two-body --set periods=2 -o " + (dir / "orbit.svg")).exit_code == 0);
  REQUIRE(run_vibra("plot elastic-pendulum --panels path,x,phase -o " + (dir / "e.pdf")).exit_code == 0);
  CHECK(std::filesystem::file_size(dir / "orbit.svg") > 1000);
  CHECK(std::filesystem::file_size(dir / "e.pdf") > 1000);
}

TEST_CASE("vibra plot refuses bad input with one line, exit code 2 and no file", "[plot]") {
  const std::pair<const char*, const char*> cases[] = {
      {"plot pendulum --panels theta,omeg -o OUT.png", "did you mean 'omega'"},
      {"plot undamped --panels u,phse -o OUT.png", "did you mean 'phase'"},
      {"plot vibration --set damping=quadratic --set b=0.2 --panels u,exact -o OUT.png", "no exact solution"},
      {"plot undamped -o OUT.jpg", ".png, .svg or .pdf"},
      {"plot undamped", "needs an output file"},
      {"plot undamped --size 10x0 -o OUT.png", "WxH"},
      {"plot undamped -o /proc/version/u.png", "not a directory"},
      {"plot undamped --set T=inf -o OUT.png", "finite end time"},
  };
  for (const auto& [args, expected] : cases) vibra::test::check_refused(args, expected);
}
