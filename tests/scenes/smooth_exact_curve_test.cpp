// A known function (the exact solution) is drawn smooth at the panel's
// resolution, not as straight segments between the solver's mesh points.
#include <catch2/catch.hpp>
#include <cmath>

#include "render/draw/canvas.hpp"
#include "scenes/panels/series_panel.hpp"

using namespace vibra;

namespace {
/// Checks, in every pixel column of the panel where the curve is drawn, that
/// the function's own pixel row lies among the curve's pixels (within 2 px).
/// Straight chords between 8 points per period miss it by up to 8% of the
/// amplitude (about 12 px here) near every peak.
void check_follows_function(const render::Canvas& canvas, const render::PlotPanel& plot,
                            const std::function<double(double)>& f, double t_drawn) {
  const render::PixelRect& area = plot.area();
  int columns = 0, missed = 0;
  for (int px = int(area.x) + 3; px < int(area.x + area.w) - 3; ++px) {
    const double t = plot.x0() + (px + 0.5 - area.x) / area.w * (plot.x1() - plot.x0());
    if (t > t_drawn) break;
    int top = 1 << 30, bottom = -1;
    for (int py = int(area.y); py < int(area.y + area.h); ++py) {
      const std::uint8_t* p = canvas.data() + py * canvas.stride() + 4 * px;  // B, G, R, A
      if (p[2] > 200 && p[1] < 90 && p[0] < 90) top = std::min(top, py), bottom = std::max(bottom, py);
    }
    if (bottom < 0) continue;
    ++columns;
    const double expected = plot.to_pixel(t, f(t)).y();
    if (expected < top - 2 || expected > bottom + 3) {
      ++missed;
      UNSCOPED_INFO("column " << px << ": function at row " << expected << ", curve rows " << top << ".." << bottom);
    }
  }
  CHECK(columns > 0.9 * (std::min(t_drawn, plot.x1()) - plot.x0()) / (plot.x1() - plot.x0()) * area.w - 8);
  CHECK(missed == 0);
}

scenes::SeriesSpec exact_series(const std::function<double(double)>& f) {
  return {"", render::Color{1, 0, 0}, [f](std::span<const double> row) { return f(row[0]); }, false, f};
}
}  // namespace

TEST_CASE("the exact solution is drawn smooth over the whole run", "[plot]") {
  const double period = 2 * M_PI, T = 2 * period, dt = period / 8;  // a coarse mesh: 8 steps per period
  const std::function<double(double)> f = [](double t) { return std::cos(t); };
  render::Canvas canvas = render::Canvas::image(800, 400);
  canvas.clear(render::Color{1, 1, 1});
  scenes::SeriesPanel panel({0, 0, 800, 400}, 1, "u", {exact_series(f)}, T, scenes::WindowMode::whole_run, 0);
  for (int n = 0; n * dt <= T * (1 + 1e-12); ++n) panel.record(std::vector<double>{n * dt, f(n * dt)});
  panel.finish_recording();
  panel.draw_static(canvas, false);
  render::Canvas pristine = render::Canvas::image(800, 400);  // the layer's static drawing, for its resets
  pristine.clear(render::Color{1, 1, 1});
  panel.draw_static(pristine, false);
  pristine.flush();
  scenes::LayerGrowth first(canvas, true, &pristine), second(canvas, false, &pristine);
  panel.draw_progress(first, std::vector<double>{T / 2, f(T / 2)});
  panel.draw_progress(second, std::vector<double>{T, f(T)});  // in two pieces, as frames draw it
  canvas.flush();
  check_follows_function(canvas, panel.plot(), f, T);
}

TEST_CASE("the exact solution is drawn smooth in a moving window", "[plot]") {
  const double period = 2 * M_PI, T = 6 * period, dt = period / 8;
  const std::function<double(double)> f = [](double t) { return std::cos(t); };
  render::Canvas canvas = render::Canvas::image(800, 400);
  canvas.clear(render::Color{1, 1, 1});
  scenes::SeriesPanel panel({0, 0, 800, 400}, 1, "u", {exact_series(f)}, T, scenes::WindowMode::movement, 2 * period);
  const double now = 5 * period + 1;
  for (int n = 0; n * dt <= T * (1 + 1e-12); ++n) panel.record(std::vector<double>{n * dt, f(n * dt)});
  panel.finish_recording();
  for (int n = 0; n * dt <= now; ++n) panel.observe(std::vector<double>{n * dt, f(n * dt)});
  panel.draw(canvas, now, std::vector<double>{now, f(now)}, false);
  canvas.flush();
  check_follows_function(canvas, panel.plot(), f, now);
}
