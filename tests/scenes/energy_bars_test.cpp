// Energy bars: kinetic, potential and dissipated energy add up to E(0) plus
// the forcing's work, dissipated stays 0 without damping, and the bars stay
// inside their area.
#include <catch2/catch.hpp>

#include <cmath>
#include <memory>

#include "cli_support.hpp"
#include "core/error.hpp"
#include "render/draw/text.hpp"
#include "scenes/panels/energy_bars.hpp"
#include "test_support.hpp"

using namespace vibra;
using scenes::EnergyBars;

namespace {
/// Bars fed a whole run as a render feeds them: the pre-pass, then the steps again.
struct FedBars {
  std::vector<std::vector<double>> rows;
  EnergyBars bars;
  explicit FedBars(Trajectory& run) : rows(test::rows(run)), bars(run.info()) {
    for (const auto& row : rows) bars.record(row);
  }
};

double total(const scenes::EnergyBudget& b) { return b.kinetic + b.potential + b.dissipated; }

/// A forced, damped vibration's four bars placed in `area` and drawn at its
/// last row on a paper canvas of width x height.
struct DrawnBars {
  std::unique_ptr<Trajectory> run = test::trajectory("vibration", {"b=0.2", "F=cos(t)"});
  FedBars fed{*run};
  render::Canvas canvas;
  DrawnBars(const render::PixelRect& area, int width, int height) : canvas(render::Canvas::image(width, height)) {
    fed.bars.place(area, 1);
    fed.bars.observe(fed.rows.back());
    canvas.clear(render::palette::paper);
    fed.bars.draw(canvas, fed.rows.back());
    canvas.flush();
  }
};
}  // namespace

TEST_CASE("an unforced damped run's bars add up to E(0), dissipated growing to what was lost", "[energy-bars]") {
  for (const std::string model : {"vibration", "pendulum", "sliding-box"}) {
    INFO(model);
    auto run = test::trajectory(model, model == "vibration" ? std::vector<std::string>{"b=0.3", "periods=4"}
                                                             : std::vector<std::string>{"periods=4"});
    REQUIRE(run->info().damped);
    FedBars fed(*run);
    const double E0 = run->info().energy(fed.rows[0]).total();
    for (const auto& row : fed.rows) {
      fed.bars.observe(row);
      CHECK(total(fed.bars.at(row)) == Approx(E0).epsilon(1e-12));
    }
    const auto last = fed.bars.at(fed.rows.back());
    CHECK(last.dissipated > 0.3 * E0);  // a real loss over four periods
    CHECK(last.dissipated == Approx(E0 - run->info().energy(fed.rows.back()).total()).epsilon(1e-12));
  }
}

TEST_CASE("dissipated stays 0 without damping, forced or not", "[energy-bars]") {
  struct Case {
    std::string model;
    std::vector<std::string> settings;
    double tolerance;  ///< of max energy: the scheme's error in E, and the work's quadrature
  };
  // RK4 loses energy as (w dt)^4: 1e-7 at 400 steps a period, and the
  // work's quadrature is 4th order too (its order is tested below).
  for (const Case& c : {Case{"undamped", {"scheme=rk4", "steps_per_period=400", "periods=5"}, 1e-7},
                        Case{"vibration", {"b=0", "F=0.5*cos(0.7*t)", "scheme=rk4", "steps_per_period=400", "periods=5"}, 1e-7},
                        Case{"resonance", {"beta=0", "scheme=rk4", "steps_per_period=400", "periods=5"}, 1e-7},
                        Case{"vibration", {"b=0", "F=sin(3*t)", "k=4", "scheme=rk4", "steps_per_period=2000", "periods=2"}, 1e-9}}) {
    INFO(c.model);
    auto run = test::trajectory(c.model, c.settings);
    REQUIRE(!run->info().damped);
    FedBars fed(*run);
    double largest_E = 0, worst = 0, moved = 0;
    for (const auto& row : fed.rows) {
      fed.bars.observe(row);
      const auto b = fed.bars.at(row);
      largest_E = std::max(largest_E, std::abs(b.kinetic + b.potential));
      // The first three steps' work is 3rd order until the fourth sample
      // lets the cubic through the opening integrate them again.
      if (&row >= &fed.rows[3]) worst = std::max(worst, std::abs(b.dissipated));
      moved = std::max(moved, std::abs(b.kinetic + b.potential - run->info().energy(fed.rows[0]).total()));
    }
    CHECK(worst < c.tolerance * largest_E);
    if (c.model != "undamped") CHECK(moved > 0.1 * largest_E);  // the force did real work
  }
}

TEST_CASE("the forcing's work converges at fourth order in dt", "[energy-bars]") {
  auto dissipated_at_end = [](int steps) {
    auto run = test::trajectory("vibration", {"b=0", "F=cos(0.7*t)", "scheme=rk4", "steps_per_period=" + std::to_string(steps),
                                              "periods=3"});
    FedBars fed(*run);
    for (const auto& row : fed.rows) fed.bars.observe(row);
    return std::abs(fed.bars.at(fed.rows.back()).dissipated);
  };
  const double coarse = dissipated_at_end(40), fine = dissipated_at_end(80);
  CHECK(coarse > 1e-9);
  CHECK(std::log2(coarse / fine) >= 3.7);  // RK4's energy error and the quadrature's are both 4th order
}

TEST_CASE("the work is exact for a cubic power, between samples too", "[energy-bars]") {
  // P(t) = t^3 - 2t: W(t) = t^4/4 - t^2, on an uneven mesh, read between samples.
  scenes::ForcingWork work;
  auto P = [](double t) { return t * t * t - 2 * t; };
  auto W = [](double t) { return t * t * t * t / 4 - t * t; };
  // Exact once four points pin the cubic: the total from the fourth sample
  // on, a read between samples from the third on (with its own point).
  double t = 0;
  int n = 0;
  for (double h : {0.1, 0.3, 0.05, 0.2, 0.25, 0.1, 0.15}) {
    work.add(t, P(t));
    ++n;
    if (n >= 4) CHECK(work.total() == Approx(W(t)).margin(1e-13));
    const double mid = t + 0.4 * h;
    if (n >= 3) CHECK(work.at(mid, P(mid)) == Approx(W(mid)).margin(1e-13));
    t += h;
  }
}

TEST_CASE("with a driving force a fourth bar shows its work, and the bars balance at every frame", "[energy-bars]") {
  auto run = test::trajectory("vibration", {"b=0.1", "F=0.4*sin(3*t)", "k=4", "steps_per_period=40", "periods=3"});
  FedBars fed(*run);
  CHECK(fed.bars.bars() == 4);
  auto frames = test::trajectory("vibration", {"b=0.1", "F=0.4*sin(3*t)", "k=4", "steps_per_period=40", "periods=3"});
  const double E0 = run->info().energy(fed.rows[0]).total();
  std::vector<double> row(frames->width());
  frames->row(row);
  fed.bars.observe(row);
  while (frames->advance()) {
    frames->row_at(frames->t() - 0.37 * frames->info().mesh.dt, row);  // a frame after the last step observed
    const auto b = fed.bars.at(row);
    CHECK(b.kinetic + b.potential + b.dissipated == Approx(E0 + b.work).margin(1e-12));
    frames->row(row);
    fed.bars.observe(row);
  }
  auto unforced = test::trajectory("vibration", {"b=0.1"});
  CHECK(FedBars(*unforced).bars.bars() == 3);
}

TEST_CASE("bars never leave their area, between steps included", "[energy-bars]") {
  for (const std::string model : {"vibration", "two-body", "bouncing-ball", "pendulum"}) {
    INFO(model);
    auto run = test::trajectory(model, model == "vibration" ? std::vector<std::string>{"b=0.2", "F=cos(t)"}
                                                             : std::vector<std::string>{});
    FedBars fed(*run);
    fed.bars.place({100, 50, 120, 400}, 1);
    const render::PixelRect inner = fed.bars.bars_area();
    CHECK(inner.x >= 100);
    CHECK(inner.y >= 50);
    CHECK(inner.y + inner.h <= 450);
    auto between = test::trajectory(model, model == "vibration" ? std::vector<std::string>{"b=0.2", "F=cos(t)"}
                                                                 : std::vector<std::string>{});
    std::vector<double> row(between->width());
    do {
      between->row(row);
      fed.bars.observe(row);
      between->row_at(between->t() - 0.37 * between->info().mesh.dt, row);  // a frame between two steps
      const auto px = fed.bars.bar_pixels(row);
      for (int i = 0; i < fed.bars.bars(); ++i) {
        CHECK(px.top[i] >= inner.y);
        CHECK(px.bottom[i] <= inner.y + inner.h);
        CHECK(px.top[i] <= px.bottom[i]);
      }
    } while (between->advance());
    CHECK(fed.bars.lo() <= 0);
    CHECK(fed.bars.hi() >= 0);
  }
}

TEST_CASE("bars for a model without a mechanical energy are refused", "[energy-bars]") {
  TrajectoryInfo info;
  info.columns = {"t", "u", "v"};
  CHECK_THROWS_AS(EnergyBars(info), UsageError);
  CHECK_THROWS_WITH(EnergyBars(info), Catch::Contains("drop --energy-bars"));
}

TEST_CASE("energy bars need a diagram to stand beside", "[energy-bars]") {
  test::check_refused("render pendulum --layout plot --energy-bars --at 1 -o OUT.png", "use --layout fbd or fbd+plot");
  test::ScratchDirectory dir;
  CHECK(test::run_vibra("render pendulum --layout fbd --energy-bars --at 1 -q -o " + (dir / "fbd.png")).exit_code == 0);
}

TEST_CASE("the bars' names are written under the bars, inside the panel, not above it", "[energy-bars]") {
  const render::PixelRect area{100, 50, 160, 400};
  const DrawnBars drawn(area, 400, 500);
  const FedBars& fed = drawn.fed;
  const render::Canvas& canvas = drawn.canvas;
  // Dark text pixels (the names are in ink) in a band of rows, across the panel's width.
  const auto dark_pixels = [&](double y0, double y1) {
    int n = 0;
    for (int y = std::max(0, int(y0)); y < std::min(500, int(y1)); ++y)
      for (int x = int(area.x); x < int(area.x + area.w); ++x) {
        const std::uint8_t* p = canvas.data() + y * canvas.stride() + 4 * x;  // B, G, R, A
        n += p[0] < 100 && p[1] < 100 && p[2] < 100;
      }
    return n;
  };
  const render::PixelRect inner = fed.bars.bars_area();
  // Two alternating lines of names, 4 and 22 px under the bars, each about 14 px high.
  CHECK(dark_pixels(inner.y + inner.h + 2, inner.y + inner.h + 42) > 100);
  CHECK(dark_pixels(0, area.y) == 0);  // nothing above the panel
}

TEST_CASE("each bar's length is its value on one scale: the same pixels per unit, up from one zero line", "[energy-bars]") {
  // The scale spans [lo, hi] with 4% headroom over the bars' rectangle; a
  // positive value rises from the zero line, a negative one hangs below it.
  for (const std::string model : {"vibration", "sliding-box", "two-body"}) {
    INFO(model);
    auto run = test::trajectory(model, model == "vibration" ? std::vector<std::string>{"b=0.2", "F=cos(t)"}
                                                             : std::vector<std::string>{"periods=2"});
    FedBars fed(*run);
    fed.bars.place({100, 50, 200, 400}, 1);
    const render::PixelRect inner = fed.bars.bars_area();
    const double per_unit = inner.h / (1.04 * (fed.bars.hi() - fed.bars.lo()));
    const double zero = inner.y + (fed.bars.lo() + 1.04 * (fed.bars.hi() - fed.bars.lo())) * per_unit;
    for (const auto& row : fed.rows) {
      fed.bars.observe(row);
      const scenes::EnergyBudget b = fed.bars.at(row);
      const double values[] = {b.kinetic, b.potential, b.dissipated, b.work};
      const auto px = fed.bars.bar_pixels(row);
      for (int i = 0; i < fed.bars.bars(); ++i) {
        CHECK(px.bottom[i] - px.top[i] == Approx(std::abs(values[i]) * per_unit).margin(1e-6));
        CHECK((values[i] >= 0 ? px.bottom[i] : px.top[i]) == Approx(zero).margin(1e-6));
      }
    }
  }
}

TEST_CASE("each bar's name is written under that bar: kinetic, potential, dissipated, work of F", "[energy-bars]") {
  // The names differ in width: under each bar, on its line (they alternate),
  // the ink is as wide as that bar's name and centred on the bar.
  DrawnBars drawn({60, 40, 320, 400}, 440, 500);
  const FedBars& fed = drawn.fed;
  render::Canvas& canvas = drawn.canvas;
  REQUIRE(fed.bars.bars() == 4);
  const render::PixelRect inner = fed.bars.bars_area();
  const double pitch = inner.w / 4;
  const char* names[] = {"kinetic", "potential", "dissipated", "work of F"};
  for (int i = 0; i < 4; ++i) {
    INFO("bar " << i << ", " << names[i]);
    const double centre = inner.x + (i + 0.5) * pitch, line = inner.y + inner.h + 4 + (i % 2) * 18;
    int left = 1 << 20, right = -1;
    for (int y = int(line); y < int(line + 16); ++y)
      for (int x = int(centre - pitch); x < int(centre + pitch); ++x) {
        const std::uint8_t* p = canvas.data() + y * canvas.stride() + 4 * x;  // B, G, R, A
        if (p[0] < 110 && p[1] < 110 && p[2] < 110) left = std::min(left, x), right = std::max(right, x);
      }
    REQUIRE(right > left);
    const double width = render::text_size(canvas, names[i], {14, render::palette::ink}).x();
    CHECK(std::abs((right + 1 - left) - width) < 4);
    CHECK(std::abs(0.5 * (left + right + 1) - centre) < 3);
  }
}
