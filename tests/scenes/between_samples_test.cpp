// A frame between two samples of a fixed-step run draws a quantity of the rows on the line between its sample values.
//
// Between t_n and t_n+1 a fixed-step run is the chord (1 - s) y_n + s y_n+1,
// and its panels join the samples' values by straight lines. A quantity
// that is not linear in the state (an energy, the orbit's radius) has less
// on the chord than on that line: a circle's chord lies inside it. The
// frame must end each curve where the curve runs, so these tests know the
// answer from the samples' own values and the chord's geometry.
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "core/comparison_trajectory.hpp"
#include "render/draw/canvas.hpp"
#include "scenes/config/scene_config.hpp"
#include "scenes/panels/energy_bars.hpp"
#include "scenes/panels/history_feed.hpp"
#include "scenes/panels/series_panel.hpp"
#include "scenes/scene_factory.hpp"
#include "scenes/system_scene.hpp"
#include "test_support.hpp"

using namespace vibra;

namespace {
constexpr double kOmega = 2 * M_PI;

/// Samples of u = cos(w t), v = -w sin(w t) (period 1), `steps` a period:
/// each on the circle u^2 + (v/w)^2 = 1.
std::vector<std::vector<double>> circle_samples(int steps, int periods) {
  std::vector<std::vector<double>> rows;
  for (int n = 0; n <= steps * periods; ++n) {
    const double t = double(n) / steps;
    rows.push_back({t, std::cos(kOmega * t), -kOmega * std::sin(kOmega * t)});
  }
  return rows;
}

std::vector<double> chord(const std::vector<double>& a, const std::vector<double>& b, double s) {
  std::vector<double> row(a.size());
  for (size_t c = 0; c < a.size(); ++c) row[c] = (1 - s) * a[c] + s * b[c];
  return row;
}

double squared_radius(std::span<const double> r) { return r[1] * r[1] + r[2] * r[2] / (kOmega * kOmega); }
double squared_u(std::span<const double> r) { return r[1] * r[1]; }

/// A whole-run panel of u^2 + (v/w)^2 and u^2 over the samples, after its pre-pass.
scenes::SeriesPanel recorded_panel(const std::vector<std::vector<double>>& rows, double T) {
  scenes::SeriesPanel panel({0, 0, 640, 360}, render::scale_for_height(360), "r",
                            {{"", render::Color{0, 0, 1}, squared_radius}, {"", render::Color{1, 0, 0}, squared_u}}, T,
                            scenes::WindowMode::whole_run, 0);
  for (const auto& row : rows) panel.record(row);
  panel.finish_recording();
  return panel;
}

bool inside_plot(const render::PlotPanel& plot, double t, double value) {
  const double y = plot.to_pixel(t, value).y();
  return plot.area().y <= y && y <= plot.area().y + plot.area().h;
}

/// The next samples of one run: `row` alone.
std::vector<std::vector<double>> next_of(const std::vector<double>& row) { return {row}; }

/// A scene that keeps the next samples it is given before each frame.
struct LookAheadScene final : scenes::Scene {
  std::vector<std::vector<std::vector<double>>> ahead;
  void record(std::span<const double>) override {}
  void observe(std::span<const double>) override {}
  void look_ahead(std::span<const std::vector<double>> next) override { ahead.emplace_back(next.begin(), next.end()); }
  void draw(render::Canvas&, std::span<const double>) override {}
  void skip(const render::Canvas&, std::span<const double>) override {}
};
}  // namespace

TEST_CASE("between two samples a panel draws a quantity on the line between its sample values, not of the chord's state",
          "[discrete-curve]") {
  const auto rows = circle_samples(4, 2);
  scenes::SeriesPanel panel = recorded_panel(rows, 2);
  // The render pass has observed sample 1 (a quarter period) and knows sample 2.
  panel.observe(rows[1]);
  panel.look_ahead(next_of(rows[2]));
  for (double s : {0.1, 0.5, 0.9}) {
    INFO("s = " << s);
    const double t = (1 + s) / 4;
    const std::vector<double> state = chord(rows[1], rows[2], s);
    // The chord's state lies inside the circle: 1 - 2 s (1 - s) (a half at mid-step).
    REQUIRE(squared_radius(state) == Approx(1 - 2 * s * (1 - s)).margin(1e-12));
    CHECK(panel.value_drawn(0, t, state) == Approx(1).margin(1e-12));
    // u^2 from 0 at sample 1 to 1 at sample 2: s on the line, s^2 on the chord.
    CHECK(panel.value_drawn(1, t, state) == Approx(s).margin(1e-12));
    CHECK(squared_u(state) == Approx(s * s).margin(1e-12));
    // Inside the panel's range, which the samples set.
    CHECK(inside_plot(panel.plot(), t, panel.value_drawn(0, t, state)));
  }
  // Without a next sample (a run curved between its samples) or at a sample,
  // the value of the row itself.
  const std::vector<double> state = chord(rows[1], rows[2], 0.5);
  panel.look_ahead({});
  CHECK(panel.value_drawn(0, 0.375, state) == Approx(0.5).margin(1e-12));
  // A next sample without a value of the series (another run's): none either.
  std::vector<double> other_run = rows[2];
  other_run[1] = other_run[2] = NAN;
  panel.look_ahead(next_of(other_run));
  CHECK(panel.value_drawn(0, 0.375, state) == Approx(0.5).margin(1e-12));
  panel.look_ahead(next_of(rows[2]));
  CHECK(panel.value_drawn(0, rows[1][0], rows[1]) == Approx(1).margin(1e-12));
  CHECK(panel.value_drawn(1, rows[2][0], rows[2]) == Approx(1).margin(1e-12));
}

TEST_CASE("the render pass gives a scene the next sample of a fixed-step run between samples, and none otherwise",
          "[discrete-curve]") {
  auto run = test::trajectory("undamped", {"scheme=centered", "steps_per_period=4", "periods=2"});
  const auto samples = test::rows(*test::trajectory("undamped", {"scheme=centered", "steps_per_period=4", "periods=2"}));
  const double P = samples[4][0];  // one period
  LookAheadScene scene;
  scenes::HistoryFeed feed(*run, scene, 0);
  // Before each frame, the run's sample at or after the frame's time.
  for (const auto& [t, n] : {std::pair{0.0, 0}, std::pair{0.4 * P, 2}, std::pair{0.75 * P, 3}}) {
    INFO("t = " << t);
    feed.row_at(t);
    REQUIRE(scene.ahead.back().size() == 1);
    CHECK(scene.ahead.back()[0] == samples[n]);
  }
  // An adaptive run is drawn from its dense output between steps: no chord.
  auto adaptive = test::trajectory("undamped", {"scheme=dopri5", "periods=1"});
  LookAheadScene dense;
  scenes::HistoryFeed(*adaptive, dense, 0).row_at(0.37);
  REQUIRE(dense.ahead.size() == 1);
  CHECK(dense.ahead.back().empty());
}

TEST_CASE("energy bars between two samples hold each part on its line between the samples, adding up to E(0)",
          "[energy-bars]") {
  // The centered scheme at 4 steps a period: its samples' energies differ
  // (its energy oscillates), and the chord's state holds far less than either.
  auto run = test::trajectory("undamped", {"scheme=centered", "steps_per_period=4", "periods=2"});
  const auto rows = test::rows(*run);
  scenes::EnergyBars bars(run->info());
  for (const auto& row : rows) bars.record(row);
  const EnergyFunction& energy = run->info().energy;
  const double E0 = energy(rows[0]).total();
  for (size_t n = 0; n <= 1; ++n) bars.observe(rows[n]);
  bars.look_ahead(next_of(rows[2]));
  const double s = 0.3, t = rows[1][0] + s * (rows[2][0] - rows[1][0]);
  std::vector<double> state = chord(rows[1], rows[2], s);
  state[0] = t;
  const EnergyParts at1 = energy(rows[1]), at2 = energy(rows[2]);
  const scenes::EnergyBudget b = bars.at(state);
  CHECK(b.kinetic == Approx(at1.kinetic + s * (at2.kinetic - at1.kinetic)).margin(1e-12));
  CHECK(b.potential == Approx(at1.potential + s * (at2.potential - at1.potential)).margin(1e-12));
  CHECK(b.kinetic + b.potential + b.dissipated == Approx(E0).epsilon(1e-12));
  // The chord's state would have shown a loss the scheme never had at its samples.
  const double chord_loss = E0 - energy(state).total();
  const double most_lost = std::max(E0 - at1.total(), E0 - at2.total());
  REQUIRE(chord_loss > most_lost + 0.05 * E0);
  CHECK(b.dissipated <= most_lost + 1e-12);
}

TEST_CASE("the orbit's r - r(0) panel at a frame between steps shows PEFRL's drift, not the chord's dip", "[orbit]") {
  // At 200 steps a period a chord's middle lies 1 - cos(pi/200) = 1.2e-4
  // inside the circle, while PEFRL's radius drifts by 2e-8: the panel's
  // range. A frame between steps must stay on the curve, inside the panel.
  scenes::SceneConfig config = scenes::load_scene("orbit");
  auto pre_pass = scenes::build_scene_runs(config);
  auto scene = scenes::make_scene_for(config, *pre_pass, "test");
  std::vector<double> row(pre_pass->width());
  do {
    pre_pass->row(row);
    scene->record(row);
  } while (pre_pass->advance());
  auto live = scenes::build_scene_runs(config);
  scenes::HistoryFeed feed(*live, *scene, scene->sample_interval());
  const double dt = live->info().mesh.dt, t = 100.5 * dt;  // mid-step, half a period in
  const std::span<const double> at = feed.row_at(t);
  render::Canvas canvas = render::Canvas::image(config.width, config.height);
  scene->draw(canvas, at);
  const auto& system = dynamic_cast<const scenes::SystemScene&>(*scene);
  const auto& drift = dynamic_cast<const scenes::SeriesPanel&>(system.panel(2));
  const double r_on_chord = std::hypot(at[1], at[2]) - 1;
  REQUIRE(r_on_chord < -0.9 * (1 - std::cos(M_PI / 200)));
  const double drawn = drift.value_drawn(0, t, at);
  CHECK(std::abs(drawn) < 1e-7);
  CHECK(inside_plot(drift.plot(), t, drawn));
}

TEST_CASE("a comparison's coarse run is read at its own samples only, and drawn between them on its chord",
          "[discrete-curve][comparison]") {
  // dt = 0.2 against dt = 0.05: the union of the meshes holds the coarse run
  // between its samples three times out of four. Its energy there, of the
  // chord's state, dipped below its samples' energies: a sawtooth the scheme
  // never computed. It is read at its own samples and joined by lines.
  scenes::SceneConfig config = scenes::load_scene("spring");
  for (const auto& [k, v] : {std::pair{"compare", "dt=0.2,0.05"}, {"scheme", "centered"}, {"panels", "energy"}})
    scenes::apply_setting(config, {k, v, "test"});
  auto runs = scenes::build_scene_runs(config);
  const auto& comparison = dynamic_cast<const ComparisonTrajectory&>(*runs);
  const size_t u_coarse = comparison.offset(0), u_fine = comparison.offset(1);
  std::vector<double> row(runs->width());
  int hidden = 0, shown = 0;
  do {
    runs->row(row);
    runs->hide_runs_between_their_samples(row);
    const bool own = std::abs(row[0] / 0.2 - std::round(row[0] / 0.2)) < 1e-9;
    INFO("t = " << row[0]);
    CHECK(std::isfinite(row[u_coarse]) == own);
    CHECK(std::isfinite(row[u_fine]));
    (own ? shown : hidden) += 1;
  } while (runs->advance());
  CHECK(shown > 90);  // 3 periods at dt = 0.2
  CHECK(hidden > 2 * shown);

  // The drawn energy of the coarse run at a frame between its samples: on
  // the line between its energies there, from its own run.
  auto pre_pass = scenes::build_scene_runs(config);
  auto scene = scenes::make_scene_for(config, *pre_pass, "test");
  scenes::HistoryFeed(*pre_pass, *scene, scene->sample_interval()).record_all([](std::span<const double>) {});
  auto live = scenes::build_scene_runs(config);
  scenes::HistoryFeed feed(*live, *scene, scene->sample_interval());
  const double t = 2.35;  // between the coarse samples 2.2 and 2.4, on the fine mesh
  const std::span<const double> at = feed.row_at(t);
  render::Canvas canvas = render::Canvas::image(config.width, config.height);
  scene->draw(canvas, at);
  const auto& energy = dynamic_cast<const scenes::SeriesPanel&>(dynamic_cast<const scenes::SystemScene&>(*scene).panel(0));
  auto coarse = test::trajectory("vibration", {"scheme=centered", "dt=0.2", "m=1", "k=1", "I=1", "V=0", "T=20"});
  const auto samples = test::rows(*coarse);
  const EnergyFunction& E = coarse->info().energy;
  const double E0 = E(samples[0]).total();
  auto relative = [&](size_t n) { return (E(samples[n]).total() - E0) / std::abs(E0); };
  REQUIRE(samples[11][0] == Approx(2.2));
  const double s = (t - samples[11][0]) / (samples[12][0] - samples[11][0]);
  CHECK(energy.value_drawn(0, t, at) == Approx(relative(11) + s * (relative(12) - relative(11))).margin(1e-12));
}

TEST_CASE("a comparison's legend takes a run between its samples for a run still going, not one that blew up",
          "[comparison]") {
  // Reading NaN between its samples, the coarse run was taken for one that
  // blew up: its legend entry got a note's row, empty, under it.
  scenes::SceneConfig config = scenes::load_scene("spring");
  for (const auto& [k, v] : {std::pair{"compare", "dt=0.2,0.05"}, {"scheme", "centered"}})
    scenes::apply_setting(config, {k, v, "test"});
  auto pre_pass = scenes::build_scene_runs(config);
  auto scene = scenes::make_scene_for(config, *pre_pass, "test");
  scenes::HistoryFeed(*pre_pass, *scene, scene->sample_interval()).record_all([](std::span<const double>) {});
  auto live = scenes::build_scene_runs(config);
  scenes::HistoryFeed feed(*live, *scene, scene->sample_interval());
  render::Canvas canvas = render::Canvas::image(config.width, config.height);
  scene->draw(canvas, feed.row_at(1));
  std::vector<double> rows;  // the legend's text rows, top to bottom
  for (const auto& shape : scene->last_layout()->outline.shapes())
    if (shape.kind == render::OutlineKind::text && shape.name.find("<i>t</i> = 0.") != std::string::npos)
      rows.push_back(shape.bounds.y + shape.bounds.h / 2);
  REQUIRE(rows.size() == 2);
  // The next row (the exact solution's) is as far below the second as the second below the first.
  double exact = NAN;
  for (const auto& shape : scene->last_layout()->outline.shapes())
    if (shape.kind == render::OutlineKind::text && shape.name == "exact") exact = shape.bounds.y + shape.bounds.h / 2;
  REQUIRE(std::isfinite(exact));
  CHECK(rows[1] - rows[0] == Approx(exact - rows[1]).margin(1));
}
