// The panels `vibra render --panels` offers: their values from the run's rows
// (the energy panel equals `vibra solve --energy`), their errors, and stills
// of every kind for every built-in scene, whole run and windowed.
#include <catch2/catch.hpp>

#include <array>
#include <cmath>

#include "cli_support.hpp"
#include "core/error.hpp"
#include "scenes/panels/period_track.hpp"
#include "scenes/panels/quantity_panels.hpp"
#include "scenes/panels/series_panel.hpp"
#include "scenes/config/scene_config.hpp"
#include "test_support.hpp"

using namespace vibra;
using scenes::quantity_panel;

namespace {
const render::Color kBlue = render::palette::blue, kRed = render::palette::vermillion;
}

TEST_CASE("the energy panel's values are solve --energy's E_rel at the same steps", "[panels]") {
  for (const std::string settings : {"vibration --set b=0.3 --set scheme=centered", "pendulum --set scheme=forward-euler",
                                      "two-body --set vy0=1.2 --set scheme=rk4 --set steps_per_period=30"}) {
    INFO(settings);
    const auto solved = test::run_vibra("solve " + settings + " --set periods=2 --energy");
    REQUIRE(solved.exit_code == 0);
    const auto cells = test::csv_rows(solved.out);
    REQUIRE(cells[0].back() == "E_rel");

    // The same run in this process, its rows fed to the panel in time order.
    std::vector<std::string> keys;
    for (size_t at = settings.find("--set "); at != std::string::npos; at = settings.find("--set ", at + 1))
      keys.push_back(settings.substr(at + 6, settings.find(' ', at + 6) - at - 6));
    keys.push_back("periods=2");
    auto run = test::trajectory(settings.substr(0, settings.find(' ')), keys);
    const auto spec = quantity_panel("energy", run->info(), kBlue, "", kRed);
    REQUIRE(spec.curves.size() == 1);
    const auto rows = test::rows(*run);
    REQUIRE(rows.size() + 1 == cells.size());
    double largest = 0;
    for (size_t n = 0; n < rows.size(); ++n) {
      const double panel = spec.curves[0].value(rows[n]);
      CHECK(panel == Approx(std::stod(cells[n + 1].back())).margin(1e-15).epsilon(1e-14));
      largest = std::max(largest, std::abs(panel));
    }
    CHECK(largest > 1e-6);  // a real change, not zeros compared
  }
}

TEST_CASE("the error panel is the main quantity minus the exact solution", "[panels]") {
  auto run = test::trajectory("undamped", {"scheme=forward-euler", "steps_per_period=20", "periods=3"});
  const auto spec = quantity_panel("error", run->info(), kBlue, "", kRed);
  for (const auto& row : test::rows(*run)) CHECK(spec.curves[0].value(row) == row[1] - run->info().exact(row[0]));
  CHECK_THROWS_WITH(quantity_panel("error", test::trajectory("vibration", {"b=0.2", "F=cos(t)"})->info(), kBlue, "", kRed),
                    Catch::StartsWith("this run has no exact solution") && Catch::Contains("drop 'error'"));
}

TEST_CASE("a column panel overlays the exact solution on the main quantity only", "[panels]") {
  auto run = test::trajectory("undamped", {"periods=1"});
  const auto u = quantity_panel("u", run->info(), kBlue, "", kRed);
  REQUIRE(u.references.size() == 1);
  CHECK(u.references[0].dashed);
  CHECK(quantity_panel("v", run->info(), kBlue, "", kRed).references.empty());
  const auto phase = quantity_panel("phase", run->info(), kBlue, "", kRed);
  REQUIRE(phase.is_phase());
  const std::vector<double> row = {0.5, 0.25, -2};
  CHECK(phase.phase[0].x(row) == 0.25);
  // v over w = 2 pi / P (P = 1 here), at one scale with u: the orbit a circle.
  CHECK(phase.phase[0].y(row) == Approx(-2 / (2 * M_PI)).epsilon(1e-15));
  CHECK(phase.equal_scales);
  CHECK(phase.label == "<i>v</i> / <i>ω</i>");
}

TEST_CASE("the period panel steps at each crossing and holds the exact period dashed", "[panels]") {
  auto run = test::trajectory("pendulum", {"alpha=0", "Theta=90", "scheme=rk4", "steps_per_period=200", "periods=5"});
  const TrajectoryInfo& info = run->info();
  auto spec = quantity_panel("period", info, kBlue, "", kRed);
  REQUIRE(spec.references.size() == 1);
  CHECK(spec.references[0].label == "4<i>K</i>(sin <i>Θ</i>/2)");  // named by its formula
  CHECK(spec.references[0].value({}) == info.exact_period);
  CHECK(spec.least_span > 0);
  const auto rows = test::rows(*run);
  int measured = 0;
  for (const auto& row : rows) {
    const double P = spec.curves[0].value(row);
    if (std::isnan(P)) {
      CHECK(measured == 0);  // NaN only before the first period completes
      continue;
    }
    ++measured;
    CHECK(P == Approx(info.exact_period).epsilon(1e-6));
  }
  CHECK(measured > 0);
  CHECK(info.exact_period > info.mesh.period * 1.15);  // 90 degrees: clearly slower than small-angle
  // A second pass over the same rows (the render after the pre-pass) gives the same values.
  auto again = quantity_panel("period", info, kBlue, "", kRed);
  for (const auto& row : rows) again.curves[0].value(row);
  for (size_t n = 0; n < rows.size(); n += 37) {
    const double a = spec.curves[0].value(rows[n]), b = again.curves[0].value(rows[n]);
    CHECK(((std::isnan(a) && std::isnan(b)) || a == b));
  }
  // Without an exact period the small-oscillation one stands in, and says so.
  auto damped = quantity_panel("period", test::trajectory("pendulum", {"alpha=0.3"})->info(), kBlue, "", kRed);
  CHECK(damped.references.at(0).label == "2π, small angles");
  auto spring = quantity_panel("period", test::trajectory("undamped", {})->info(), kBlue, "", kRed);
  CHECK(spring.references.at(0).label == "2π/<i>ω</i>");
  auto damped_spring = quantity_panel("period", test::trajectory("vibration", {"b=0.1"})->info(), kBlue, "", kRed);
  CHECK(damped_spring.references.at(0).label == "2π/ω");
}

TEST_CASE("the period track shows the last period completed by each time, the crossing's own time included",
          "[panels]") {
  // Upward zeros at exactly t = 0, 1 and 3: a period of 1, then one of 2.
  // Rows t, u, v: sin(2 pi t) up to t = 1, then sin(pi (t - 1)).
  const double w1 = 2 * M_PI, w2 = M_PI;
  const std::vector<std::array<double, 3>> rows = {
      {-0.25, -1, 0}, {0, 0, w1},  {0.25, 1, 0}, {0.5, 0, -w1}, {0.75, -1, 0}, {1, 0, w1},
      {1.5, 1, 0},    {2, 0, -w2}, {2.5, -1, 0}, {3, 0, w2},    {3.5, 1, 0}};
  const std::vector<double> expected = {NAN, NAN, NAN, NAN, NAN, 1, 1, 1, 1, 2, 2};
  scenes::PeriodTrack track(1, 2);
  for (size_t i = 0; i < rows.size(); ++i) {
    INFO("t = " << rows[i][0]);
    const double P = track.at(rows[i]);
    if (std::isnan(expected[i])) CHECK(std::isnan(P));
    else CHECK(P == Approx(expected[i]).margin(1e-12));
  }
  // Asked again afterwards, in any order (a later pass, a frame between steps).
  CHECK(track.at(std::array<double, 3>{1, 0, w1}) == Approx(1).margin(1e-12));
  CHECK(track.at(std::array<double, 3>{2.99, -0.03, w2}) == Approx(1).margin(1e-12));
  CHECK(track.at(std::array<double, 3>{3, 0, w2}) == Approx(2).margin(1e-12));
  CHECK(std::isnan(track.at(std::array<double, 3>{0.99, -0.06, w1})));
}

TEST_CASE("the period panel of a compared run reads its own samples: the NaN rows between them add no crossing",
          "[panels]") {
  // A coarse member of a comparison is NaN at the fine run's times between
  // its own samples. Its periods must be those of its samples alone: a NaN
  // taken as a sample would hide the sign change across it, and the crossing.
  // u = sin(t), v = cos(t) every 0.1, a NaN row between each two.
  scenes::PeriodTrack with_gaps(1, 2), samples_only(1, 2);
  double last = NAN;
  for (int k = 0; k <= 2 * 260; ++k) {
    const double t = 0.05 * k;
    const std::array<double, 3> row = k % 2 ? std::array<double, 3>{t, NAN, NAN}
                                            : std::array<double, 3>{t, std::sin(t), std::cos(t)};
    const double P = with_gaps.at(row);
    if (k % 2) continue;
    const double expected = samples_only.at(row);
    INFO("t = " << t);
    if (std::isnan(expected)) CHECK(std::isnan(P));
    else CHECK(P == expected);
    last = P;
  }
  CHECK(last == Approx(2 * M_PI).epsilon(1e-3));  // 13 time units: crossings at 2 pi and 4 pi
}

TEST_CASE("an unknown panel is refused with the closest name, on the command line too", "[panels]") {
  const auto info = test::trajectory("undamped", {"periods=1"})->info();
  CHECK_THROWS_WITH(quantity_panel("enrgy", info, kBlue, "", kRed),
                    "unknown panel 'enrgy' (did you mean 'energy'?): choose from u, v, phase, energy, error, period");
  test::check_refused("render spring --panels u,phse --at 1 -o OUT.png", "did you mean 'phase'?");
  test::check_refused("render spring_dashpot --panels error --at 1 -o OUT.png", "drop 'error' from --panels");
  test::check_refused("render pendulum --layout fbd --panels phase --at 1 -o OUT.png", "use --layout fbd+plot");
  test::check_refused("render pendulum --panels , --at 1 -o OUT.png", "panels is empty");
}

TEST_CASE("every panel kind draws for every built-in scene, whole run and windowed, PNG and SVG", "[panels][render]") {
  test::ScratchDirectory dir;
  for (const auto& scene : scenes::builtin_scene_names()) {
    const std::string panels = scene == "spring" ? "phase,energy,period,error" : "phase,energy,period";
    for (const std::string window : {"", " --window 2periods --window-mode jumps", " --window 3 --window-mode movement"}) {
      const std::string args = "render " + scene + " --panels " + panels + " --energy-bars --size 640x360 --at 4" + window;
      INFO(args);
      const auto png = test::run_vibra(args + " -q -o " + (dir / "still.png"));
      CHECK(png.exit_code == 0);
      CHECK(png.err.empty());
    }
    const auto svg = test::run_vibra("render " + scene + " --panels " + panels + " --at 2 -q -o " + (dir / "still.svg"));
    CHECK(svg.exit_code == 0);
    CHECK(test::read_file(dir / "still.svg").find("</svg>") != std::string::npos);
  }
}

TEST_CASE("a model without a diagram stacks its --panels against time", "[panels][render]") {
  test::ScratchDirectory dir;
  for (const std::string panels : {"u,error", "v,energy,period", "error"}) {
    const auto r = test::run_vibra("render undamped --panels " + panels + " --at 3 -q -o " + (dir / "still.png"));
    INFO(panels << ": " << r.err);
    CHECK(r.exit_code == 0);
  }
  // The panels are the ones asked for: a note can point at each, and at no other.
  const auto at_error = test::run_vibra("render undamped --panels u,error --note '1-2: the error grows @error' --at 1.5 -q -o " +
                                        (dir / "note.png"));
  INFO(at_error.err);
  CHECK(at_error.exit_code == 0);
  test::check_refused("render undamped --panels u,error --note '1-2: here @v' --at 1.5 -o OUT.png",
                      "which is no panel here: choose one of u, error");
  test::check_refused("render undamped --panels u,phase --at 1 -o OUT.png", "panel 'phase' is the phase plane");
  test::check_refused("render undamped --compare scheme=centered,rk4 --panels u,error --at 1 -o OUT.png",
                      "panels are drawn beside the diagram");
}

TEST_CASE("a scene file chooses panels and energy bars", "[panels]") {
  scenes::SceneConfig config = scenes::parse_scene("model = \"undamped\"\npanels = \"u, phase,energy\"\nenergy_bars = true\n",
                                                   "lecture.toml");
  CHECK(config.panels == std::vector<std::string>{"u", "phase", "energy"});
  CHECK(config.energy_bars);
  CHECK_THROWS_WITH(scenes::parse_scene("panels = \" , \"\n", "lecture.toml"), Catch::Contains("panels is empty"));
}

TEST_CASE("a window narrower than the run moves the panels' time axis, one wider than the run leaves it whole",
          "[panels][render]") {
  // T = 8 at t = 7: a window of 2 shows 5..7; one of 9 covers the whole run, as no window does.
  test::ScratchDirectory dir;
  const auto still = [&](const std::string& window, const std::string& name) {
    const auto r = test::run_vibra("render pendulum --set T=8 --at 7 --size 320x180" + window + " -q -o " + (dir / name));
    INFO(r.err);
    CHECK(r.exit_code == 0);
    return test::read_file(dir / name);
  };
  // Compared as booleans: Catch would print the pictures' bytes.
  const std::string whole = still("", "whole.png");
  const bool narrow_moves = still(" --window 2", "narrow.png") != whole;
  const bool jumps_move = still(" --window 2 --window-mode jumps", "jumps.png") != whole;
  const bool wide_stays = still(" --window 9", "wide.png") == whole;
  CHECK(narrow_moves);
  CHECK(jumps_move);
  CHECK(wide_stays);
}

TEST_CASE("each window mode's time axis at t: drawing the current window, movement the last w, jumps the last complete one",
          "[panels]") {
  // A window of 2 over a run of 10: at t = 5.1 drawing shows 4..6, movement
  // 3.1..5.1 and jumps 2..4 (4..6 is not complete); before t = 2 all show 0..2.
  auto run = test::trajectory("undamped", {"T=10", "dt=0.05"});
  const auto rows = test::rows(*run);
  const auto axis_at = [&](scenes::WindowMode mode, double t) {
    scenes::SeriesPanel panel({0, 0, 640, 240}, 1, "<i>u</i>",
                              {{"", render::palette::blue, [](std::span<const double> r) { return r[1]; }}}, 10, mode, 2);
    for (const auto& row : rows) panel.record(row);
    panel.finish_recording();
    std::vector<double> now;
    for (const auto& row : rows)
      if (row[0] <= t + 1e-9) panel.observe(row), now = row;
    render::Canvas canvas = render::Canvas::image(640, 240);
    panel.draw(canvas, t, now, true);
    return std::pair{panel.plot().x0(), panel.plot().x1()};
  };
  using scenes::WindowMode;
  CHECK(axis_at(WindowMode::drawing, 5.1) == std::pair{4.0, 6.0});
  const auto moving = axis_at(WindowMode::movement, 5.1);
  CHECK(moving.first == Approx(3.1));
  CHECK(moving.second == Approx(5.1));
  CHECK(axis_at(WindowMode::jumps, 5.1) == std::pair{2.0, 4.0});
  for (WindowMode mode : {WindowMode::drawing, WindowMode::movement, WindowMode::jumps})
    CHECK(axis_at(mode, 1.3) == std::pair{0.0, 2.0});
}
