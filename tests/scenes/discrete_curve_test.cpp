// A discrete solution is drawn as what it is: mesh values joined by straight lines, marked where far apart, never past t.
//
// A fixed-step scheme computes values at t_n = n dt and nothing between
// them. The book draws such runs as their mesh values joined by straight
// lines (Figs 1.2-1.11), and the chapter's lesson is what those values do at
// 4 to 12 steps a period: a smooth interpolant through them would draw
// extrema the scheme never computed. These tests know the answer from the
// mathematics: the centered scheme's exact discrete solution cos(w~ t_n),
// w~ = (2/dt) asin(w dt/2) (1.41), and the straight segments between.
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "core/time_mesh.hpp"
#include "render/draw/canvas.hpp"
#include "scenes/panels/history_feed.hpp"
#include "scenes/panels/series_panel.hpp"
#include "test_support.hpp"

using namespace vibra;

namespace {

/// The undamped oscillator u'' + w^2 u = 0 with w = 2 pi (period 1), u(0) = 1,
/// u'(0) = 0, under the centered scheme: u_n = cos(w~ n dt) (1.41).
double centered_mesh_value(int steps_per_period, int n) {
  const double w = 2 * M_PI, dt = 1.0 / steps_per_period;
  const double w_tilde = 2 / dt * std::asin(w * dt / 2);
  return std::cos(w_tilde * n * dt);
}

/// A scene that keeps every row it is fed, and which of them were steps.
struct RecordingScene final : scenes::Scene {
  std::vector<double> recorded, recorded_between, observed, observed_between;
  double interval = 0;
  void record(std::span<const double> row) override { recorded.push_back(row[0]); }
  void observe(std::span<const double> row) override { observed.push_back(row[0]); }
  void record_between(std::span<const double> row) override { recorded_between.push_back(row[0]); }
  void observe_between(std::span<const double> row) override { observed_between.push_back(row[0]); }
  double sample_interval() const override { return interval; }
  void draw(render::Canvas&, std::span<const double>) override {}
  void skip(const render::Canvas&, std::span<const double>) override {}
};

constexpr render::Color kCurve{0, 0, 1};

/// Painted solid in the curve's blue; or, `faintly`, blue at all (a
/// thumbnail's one-pixel line is spread over two rows of pixels).
bool is_curve_pixel(const render::Canvas& canvas, int x, int y, bool faintly = false) {
  const std::uint8_t* p = canvas.data() + y * canvas.stride() + 4 * x;  // B, G, R, A
  if (faintly) return p[0] > p[2] + 40;
  return p[0] > 200 && p[1] < 80 && p[2] < 80;
}

double distance_to_segment(const render::Point& p, const render::Point& a, const render::Point& b) {
  const render::Point d = b - a;
  const double s = d.squaredNorm() > 0 ? std::clamp((p - a).dot(d) / d.squaredNorm(), 0.0, 1.0) : 0;
  return (p - (a + s * d)).norm();
}

/// A whole-run panel of one curve through `rows` ({t, u}), drawn up to t_end
/// on a white canvas of the given size, in two pieces as a video's layer grows.
struct DrawnPanel {
  render::Canvas canvas;
  scenes::SeriesPanel panel;
  DrawnPanel(int width, int height, const std::vector<std::vector<double>>& rows, double T, double mesh_dt,
             double until, scenes::WindowMode mode = scenes::WindowMode::whole_run, double window = 0)
      : canvas(render::Canvas::image(width, height)),
        panel({0, 0, double(width), double(height)}, render::scale_for_height(height), "u",
              {{"", kCurve, [](std::span<const double> r) { return r[1]; }}}, T, mode, window) {
    panel.mark_mesh_points(mesh_dt);
    for (const auto& row : rows) panel.record(row);
    panel.finish_recording();
    canvas.clear(render::Color{1, 1, 1});
    panel.draw_static(canvas, false);
    render::Canvas pristine = render::Canvas::image(width, height);
    pristine.clear(render::Color{1, 1, 1});
    panel.draw_static(pristine, false);
    pristine.flush();
    std::vector<double> now;
    for (const auto& row : rows)
      if (row[0] <= until) now = row, panel.observe(row);
    now[0] = until;  // held: the tests' rows are what the run is at `until`
    std::vector<double> half = rows.front();
    scenes::LayerGrowth first(canvas, true, &pristine), second(canvas, false, &pristine);
    panel.draw_progress(first, half);
    panel.draw_progress(second, now);
    panel.draw(canvas, until, now, false);
    canvas.flush();
  }
};

std::vector<std::vector<double>> centered_rows(int steps_per_period, int periods) {
  std::vector<std::vector<double>> rows;
  for (int n = 0; n <= steps_per_period * periods; ++n)
    rows.push_back({double(n) / steps_per_period, centered_mesh_value(steps_per_period, n)});
  return rows;
}

}  // namespace

TEST_CASE("between mesh points a fixed-step run is the straight line between its mesh values", "[discrete-curve]") {
  allow_unstable_steps(true);  // Forward Euler at 4 steps a period is the chapter's own example
  for (const SchemeInfo& scheme : all_schemes()) {
    if (scheme.adaptive) continue;
    for (int steps : {4, 8, 12}) {
      INFO(scheme.name << " at " << steps << " steps a period");
      auto run = test::trajectory("undamped", {"scheme=" + std::string(scheme.name),
                                               "steps_per_period=" + std::to_string(steps), "periods=2"});
      REQUIRE_FALSE(run->bends_between_samples());
      std::vector<double> a(run->width()), b(run->width()), between(run->width());
      run->row(a);
      while (run->advance()) {
        run->row(b);
        for (double f : {0.1, 0.5, 0.73}) {
          const double t = a[0] + f * (b[0] - a[0]);
          run->row_at(t, between);
          for (size_t c = 1; c < 3; ++c) CHECK(between[c] == Approx(a[c] + f * (b[c] - a[c])).margin(1e-12));
        }
        a = b;
      }
    }
  }
  allow_unstable_steps(false);
}

TEST_CASE("an adaptive run and an impact bend between samples, a fixed-step run does not", "[discrete-curve]") {
  CHECK(test::trajectory("undamped", {"scheme=dopri5"})->bends_between_samples());
  CHECK(test::trajectory("undamped", {"scheme=rkf45"})->bends_between_samples());
  CHECK(test::trajectory("bouncing-ball", {})->bends_between_samples());
  CHECK_FALSE(test::trajectory("pendulum", {"scheme=rk4"})->bends_between_samples());
}

TEST_CASE("an adaptive run between its steps follows its dense output, not the chord", "[discrete-curve]") {
  auto run = test::trajectory("undamped", {"scheme=rkf45", "rtol=1e-10", "atol=1e-12", "periods=1"});
  const auto& exact = run->info().exact;
  std::vector<double> row(run->width());
  double a = run->t(), worst = 0, worst_v = 0, longest = 0;
  while (run->advance()) {
    const double b = run->t(), t = 0.5 * (a + b), h = 1e-6;
    longest = std::max(longest, b - a);
    run->row_at(t, row);
    worst = std::max(worst, std::abs(row[1] - exact(t)));
    // The exact velocity by a central difference of the exact u.
    worst_v = std::max(worst_v, std::abs(row[2] - (exact(t + h) - exact(t - h)) / (2 * h)));
    a = b;
  }
  // A chord across the longest step would miss cos(2 pi t) by about (2 pi h)^2 / 8.
  INFO("longest step " << longest << ", worst error between steps " << worst);
  REQUIRE(std::pow(2 * M_PI * longest, 2) / 8 > 1e-4);
  CHECK(worst < 1e-7);
  CHECK(worst_v < 1e-6);
}

TEST_CASE("a scene is fed a fixed-step run's mesh rows only, whatever its curves resolve", "[discrete-curve]") {
  for (int steps : {4, 8, 12}) {
    auto run = test::trajectory("undamped", {"scheme=centered", "steps_per_period=" + std::to_string(steps), "periods=3"});
    RecordingScene scene;
    scene.interval = 1e-3;  // a pixel column's worth: far finer than the mesh
    scenes::HistoryFeed(*run, scene, scene.interval).record_all([](std::span<const double>) {});
    CHECK(scene.recorded_between.empty());
    REQUIRE(scene.recorded.size() == size_t(3 * steps + 1));
    for (size_t n = 0; n < scene.recorded.size(); ++n) CHECK(scene.recorded[n] == Approx(double(n) / steps).margin(1e-14));
    // The render pass: rows up to each frame's time, none between, none after.
    auto live = test::trajectory("undamped", {"scheme=centered", "steps_per_period=" + std::to_string(steps), "periods=3"});
    scenes::HistoryFeed feed(*live, scene, scene.interval);
    const double t = 1.6 / steps;  // between t_1 and t_2
    const auto row = feed.row_at(t);
    CHECK(row[0] == t);
    CHECK(scene.observed_between.empty());
    CHECK(scene.observed == std::vector<double>{0.0, 1.0 / steps});
    // Where the run is at t: on the chord between u_1 and u_2 (1.41).
    const double u1 = centered_mesh_value(steps, 1), u2 = centered_mesh_value(steps, 2);
    CHECK(row[1] == Approx(u1 + 0.6 * (u2 - u1)).margin(1e-12));
  }
  // An adaptive run is fed its dense output between steps.
  auto adaptive = test::trajectory("undamped", {"scheme=dopri5", "periods=1"});
  RecordingScene scene;
  scene.interval = 1e-3;
  scenes::HistoryFeed(*adaptive, scene, scene.interval).record_all([](std::span<const double>) {});
  CHECK(scene.recorded_between.size() > 100);
}

TEST_CASE("a coarse run's curve lies on the straight segments between its mesh values", "[discrete-curve]") {
  for (int steps : {4, 8, 12}) {
    INFO(steps << " steps a period");
    const auto rows = centered_rows(steps, 3);
    DrawnPanel drawn(1920, 1080, rows, 3, 1.0 / steps, 3);
    const render::PlotPanel& plot = drawn.panel.plot();
    std::vector<render::Point> mesh;
    for (const auto& row : rows) mesh.push_back(plot.to_pixel(row[0], row[1]));
    const double half_width = 2.4 * 1.5 / 2, marker = drawn.panel.marker_radius(0);
    CHECK(marker > 2);  // 1/steps of 3 periods over ~1900 px: far more than 6 px apart
    // Every pixel the curve painted solid is within half its width (or a
    // marker's radius, at a mesh point) of the segments: a smooth curve
    // through 4 points a period would bulge past them by a fifth of the amplitude.
    const render::PixelRect& area = plot.area();
    long painted = 0, astray = 0;
    for (int y = int(area.y) + 1; y < int(area.y + area.h) - 1; ++y)
      for (int x = int(area.x) + 1; x < int(area.x + area.w) - 1; ++x) {
        if (!is_curve_pixel(drawn.canvas, x, y)) continue;
        ++painted;
        const render::Point p(x + 0.5, y + 0.5);
        double nearest = 1e300, nearest_mesh = 1e300;
        for (size_t k = 0; k + 1 < mesh.size(); ++k) nearest = std::min(nearest, distance_to_segment(p, mesh[k], mesh[k + 1]));
        for (const auto& m : mesh) nearest_mesh = std::min(nearest_mesh, (p - m).norm());
        const double from_cursor = (p - mesh.back()).norm();  // the cursor's disc: 5 px (720p) at the end
        if (nearest > half_width + 1 && nearest_mesh > marker + 1 && from_cursor > 5 * 1.5 + 1) {
          if (++astray < 5) UNSCOPED_INFO("pixel " << x << "," << y << " is " << nearest << " px off the segments");
        }
      }
    CHECK(painted > 1000);
    CHECK(astray == 0);
    // The segments are all there, and each mesh point is marked by a disc.
    for (size_t k = 0; k + 1 < mesh.size(); ++k) {
      const render::Point mid = 0.5 * (mesh[k] + mesh[k + 1]);
      CHECK(is_curve_pixel(drawn.canvas, int(mid.x()), int(mid.y())));
    }
    for (const auto& m : mesh) {
      // The first is cut by the panel's edge; the cursor's disc is over the last.
      if (m.x() < area.x + marker + 2 || m.x() > area.x + area.w - marker - 2) continue;
      int around = 0;
      for (int k = 0; k < 8; ++k) {
        const double a = k * M_PI / 4, r = marker - 1.2;
        around += is_curve_pixel(drawn.canvas, int(std::floor(m.x() + r * std::cos(a))), int(std::floor(m.y() + r * std::sin(a))));
      }
      CHECK(around == 8);
    }
  }
}

TEST_CASE("mesh points are marked only where they are far apart, on a fixed mesh", "[discrete-curve]") {
  const auto coarse = centered_rows(4, 3);
  CHECK(DrawnPanel(640, 360, coarse, 3, 0.25, 3).panel.marker_radius(0) > 0);
  // 200 steps a period over 3 periods in ~600 px: a point every pixel.
  const auto fine = centered_rows(200, 3);
  CHECK(DrawnPanel(640, 360, fine, 3, 1.0 / 200, 3).panel.marker_radius(0) == 0);
  // Rows of no single fixed mesh (an adaptive run): nothing marked.
  CHECK(DrawnPanel(640, 360, coarse, 3, 0, 3).panel.marker_radius(0) == 0);
  TrajectoryInfo info;
  info.mesh.scheme = parse_scheme("dopri5");
  info.mesh.dt = 0.1;
  CHECK(fixed_mesh_step(info) == 0);
  info.mesh.scheme = parse_scheme("rk4");
  CHECK(fixed_mesh_step(info) == 0.1);
  info.rows_on_one_mesh = false;
  CHECK(fixed_mesh_step(info) == 0);
}

TEST_CASE("nothing after t is drawn, however many samples a pixel column holds", "[discrete-curve]") {
  // v = -t until an impact at t = 1 turns it to +0.8; fine steps, so that a
  // 320 px panel's column holds a dozen of them. Just before the impact the
  // frame must not show the jump.
  std::vector<std::vector<double>> rows;
  for (int n = 0; n <= 4000; ++n) {
    const double t = n * 1e-3;
    rows.push_back({t, t < 1 ? -t : 0.8});
  }
  for (auto mode : {scenes::WindowMode::whole_run, scenes::WindowMode::movement}) {
    INFO((mode == scenes::WindowMode::whole_run ? "whole run" : "moving window"));
    const double before = 0.995;
    DrawnPanel drawn(320, 180, rows, 4, 1e-3, before, mode, 2);
    const render::PlotPanel& plot = drawn.panel.plot();
    REQUIRE(plot.to_pixel(before, 0).x() > plot.to_pixel(1, 0).x() - 2);  // the impact is in the frame's last column or so
    const double zero_row = plot.to_pixel(0, 0).y();
    int above = 0;
    for (int y = int(plot.area().y); y < int(zero_row) - 2; ++y)
      for (int x = int(plot.area().x); x < int(plot.area().x + plot.area().w); ++x) above += is_curve_pixel(drawn.canvas, x, y, true);
    CHECK(above == 0);
    // The curve is there up to t, down to the cursor at v(t) = -t.
    int below = 0;
    for (int y = int(zero_row) + 1; y < int(plot.area().y + plot.area().h); ++y)
      for (int x = int(plot.area().x); x < int(plot.area().x + plot.area().w); ++x) below += is_curve_pixel(drawn.canvas, x, y, true);
    CHECK(below > 50);
  }
}
