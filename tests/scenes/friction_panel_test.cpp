// `vibra plot sliding-box --panels friction` (Exercise 1.23a): the spring
// force against u, the friction band, and the run's turning points on it.
#include <catch2/catch.hpp>
#include <cmath>

#include "cli_support.hpp"
#include "png_compare.hpp"
#include "core/models/sliding_box_law.hpp"
#include "render/plot/figure.hpp"
#include "scenes/figures/friction_panel.hpp"
#include "test_support.hpp"

using namespace vibra;
using test::colour_pixels;
using test::png_size;
using test::check_refusal;
using test::run_vibra;
using test::ScratchDirectory;

namespace {
/// The panel's turning points after streaming a whole run with rows a few per pixel.
std::vector<double> panel_turns(const std::vector<std::string>& settings) {
  auto run = test::trajectory("sliding-box", settings);
  render::Figure figure(800, 600);
  scenes::FrictionPanel panel(figure, {{&run->info(), render::palette::blue, ""}});
  std::vector<double> row(run->width());
  double previous = run->t();
  run->row(row);
  panel.observe(0, row);
  while (run->advance()) {
    // Rows 1/20 of a step apart between the steps, as a figure feeds them.
    for (int k = 1; k < 20; ++k) {
      run->row_at(previous + (run->t() - previous) * k / 20, row);
      panel.observe(0, row);
    }
    run->row(row);
    panel.observe(0, row);
    previous = run->t();
  }
  panel.finish();
  return panel.turning_points(0);
}
}  // namespace

TEST_CASE("friction panel: a linear spring's turning points step in by 2 mu and the last rests inside the band",
          "[plot][sliding-box]") {
  for (double mu : {0.08, 0.13, 0.3}) {
    INFO("mu = " << mu);
    const std::vector<double> turns = panel_turns({"mu=" + test::str(mu), "steps_per_period=60"});
    // Released at u = 1 from rest: 1, -(1 - 2 mu), 1 - 4 mu, ... until |u| <= mu.
    std::vector<double> expected{1};
    while (std::abs(expected.back()) > mu) expected.push_back(2 * mu * (expected.back() > 0 ? 1 : -1) - expected.back());
    REQUIRE(turns.size() == expected.size());
    for (size_t k = 0; k < turns.size(); ++k) CHECK(turns[k] == Approx(expected[k]).margin(2e-3));
    CHECK(std::abs(turns.back()) <= mu);
  }
}

TEST_CASE("friction panel: fed only a coarse run's rows, each turning point is the sample nearer the turn", "[plot][sliding-box]") {
  // At 16 steps a period the samples either side of a turn are far apart:
  // the one where |v| is smaller is within 1e-3 of the turn's u, the other
  // some 0.06 away. The turns: 1, -(1 - 2 mu), 1 - 4 mu, ... (mu = 0.1).
  auto run = test::trajectory("sliding-box", {"mu=0.1", "steps_per_period=16"});
  render::Figure figure(800, 600);
  scenes::FrictionPanel panel(figure, {{&run->info(), render::palette::blue, ""}});
  std::vector<double> row(run->width());
  do {
    run->row(row);
    panel.observe(0, row);
  } while (run->advance());
  panel.finish();
  const std::vector<double> turns = panel.turning_points(0);
  const std::vector<double> expected{1, -0.8, 0.6, -0.4, 0.2};
  REQUIRE(turns.size() >= expected.size());
  for (size_t k = 0; k < expected.size(); ++k) CHECK(turns[k] == Approx(expected[k]).margin(2e-3));
}

TEST_CASE("friction panel: on a tanh spring, friction's work mu |b - a| is the spring energy lost between turns",
          "[plot][sliding-box]") {
  for (double alpha : {1.0, 2.5}) {
    INFO("alpha = " << alpha);
    SlidingBoxLaw law;
    law.mu = 0.1, law.alpha = alpha;
    const std::vector<double> turns = panel_turns({"mu=0.1", "alpha=" + test::str(alpha), "steps_per_period=60"});
    REQUIRE(turns.size() >= 3);
    for (size_t k = 1; k < turns.size(); ++k) {
      INFO("turn " << k << " at u = " << turns[k]);
      CHECK(law.potential(turns[k - 1]) - law.potential(turns[k]) ==
            Approx(law.mu * std::abs(turns[k] - turns[k - 1])).margin(2e-3));
    }
    CHECK(law.holds(turns.back()));
    CHECK_FALSE(law.holds(turns[turns.size() - 2]));
  }
}

TEST_CASE("friction panel: refused for models without friction, and on a page", "[plot][sliding-box]") {
  ScratchDirectory dir;
  auto r = run_vibra("plot undamped --panels friction -o " + (dir / "f.png"));
  check_refusal(r, "unknown panel 'friction'");
  r = run_vibra("plot sliding-box --panels friction -o " + (dir / "f.html"));
  check_refusal(r, "panel 'friction' is not against t");
  CHECK_FALSE(std::filesystem::exists(dir / "f.html"));
}

TEST_CASE("vibra plot sliding-box --panels friction draws each run's s(u), its turns and the band",
          "[plot][sliding-box]") {
  ScratchDirectory dir;
  auto r = run_vibra("plot sliding-box --panels friction,u --size 900x800 -o " + (dir / "one.png"));
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  CHECK(png_size(dir / "one.png") == std::make_pair(900, 800));
  // s(u) in the upper panel, u(t) in the lower: blue in both halves.
  CHECK(colour_pixels(dir / "one.png", render::palette::blue, 0, 400) > 300);
  CHECK(colour_pixels(dir / "one.png", render::palette::blue, 400, 800) > 300);
  // Comparing alpha: one curve per spring in its colour; the band is shared (same mu).
  r = run_vibra("plot sliding-box --compare alpha=0,1,2,4 --panels friction -o " + (dir / "springs.png"));
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  for (size_t m = 0; m < 4; ++m) CHECK(colour_pixels(dir / "springs.png", render::palette::series(m)) > 200);
  // Comparing mu: each run's band dashed in its colour (70% over the white paper).
  r = run_vibra("plot sliding-box --compare mu=0.05,0.2 --panels friction -o " + (dir / "bands.png"));
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  for (size_t m = 0; m < 2; ++m) {
    const render::Color c = render::palette::series(m);
    const render::Color dashed{0.7 * c.r + 0.3, 0.7 * c.g + 0.3, 0.7 * c.b + 0.3};
    CHECK(colour_pixels(dir / "bands.png", dashed, 0, -1, 40) > 300);
  }
}
