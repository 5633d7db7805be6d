// The phase-plane panel: fixed ranges from the pre-pass, a trail of bounded
// length, the current point drawn where the row puts it.
#include <catch2/catch.hpp>

#include <cmath>

#include "scenes/panels/phase_panel.hpp"
#include "test_support.hpp"

using namespace vibra;

TEST_CASE("the phase panel draws the current point at (u, v) and keeps a bounded trail", "[panels][phase]") {
  auto run = test::trajectory("undamped", {"scheme=forward-euler", "steps_per_period=400", "periods=60"});
  const auto rows = test::rows(*run);
  const render::Color color = render::palette::blue;
  scenes::PhasePanel panel({0, 0, 400, 300}, 1, "<i>u</i>", "<i>v</i>",
                           {{"", color, [](std::span<const double> r) { return r[1]; },
                             [](std::span<const double> r) { return r[2]; }}},
                           run->info().mesh.period);
  for (const auto& row : rows) panel.record(row);
  panel.finish_recording();
  // Forward Euler spirals outward: the fixed range holds the largest turn.
  const auto [x0, x1] = panel.x_range();
  CHECK(x1 >= std::abs(rows.back()[1]));
  CHECK(x0 < -1);
  for (const auto& row : rows) panel.observe(row);
  CHECK(panel.trail_size(0) <= scenes::PhasePanel::kTrailPoints + 1);
  CHECK(panel.trail_size(0) > scenes::PhasePanel::kTrailPoints / 2);

  render::Canvas canvas = render::Canvas::image(400, 300);
  canvas.clear(render::palette::paper);
  panel.draw_static(canvas, false);
  const auto& now = rows[rows.size() * 2 / 3];
  panel.draw(canvas, now[0], now, false);
  canvas.flush();
  const render::Point p = panel.pixel_of(now[1], now[2]);
  const auto word = *reinterpret_cast<const std::uint32_t*>(canvas.data() + int(p.y()) * canvas.stride() + 4 * int(p.x()));
  const int red = (word >> 16) & 255, blue = word & 255;
  CHECK(std::abs(blue - 0.70 * 255) < 30);  // the point's blue, not paper
  CHECK(red < 60);
}

TEST_CASE("a row whose u or v is not finite draws the trail alone, as a row of neither does", "[panels][phase]") {
  // A compared run that blows up can have u finite and v infinite: the trail
  // ends at its last finite point, with no current point and no broken path.
  auto run = test::trajectory("undamped", {"steps_per_period=60", "periods=2"});
  const auto rows = test::rows(*run);
  scenes::PhasePanel panel({0, 0, 400, 300}, 1, "<i>u</i>", "<i>v</i>",
                           {{"", render::palette::blue, [](std::span<const double> r) { return r[1]; },
                             [](std::span<const double> r) { return r[2]; }}},
                           run->info().mesh.period);
  for (const auto& row : rows) panel.record(row);
  panel.finish_recording();
  const size_t last = rows.size() / 2;
  for (size_t i = 0; i <= last; ++i) panel.observe(rows[i]);
  const auto picture = [&](double u, double v) {
    render::Canvas canvas = render::Canvas::image(400, 300);
    canvas.clear(render::palette::paper);
    panel.draw_static(canvas, false);
    std::vector<double> row = rows[last + 1];
    row[1] = u, row[2] = v;
    panel.draw(canvas, row[0], row, false);
    canvas.flush();
    CHECK(cairo_status(canvas.cr()) == CAIRO_STATUS_SUCCESS);
    return std::string(reinterpret_cast<const char*>(canvas.data()), std::size_t(canvas.stride()) * 300);
  };
  const std::string neither = picture(NAN, NAN);
  const bool same_without_v = picture(0.5, INFINITY) == neither;
  const bool same_without_u = picture(NAN, 0.5) == neither;
  CHECK(same_without_v);
  CHECK(same_without_u);
}

TEST_CASE("equal scales: a unit is as many pixels across as up, and the whole orbit stays in the panel", "[panels][phase]") {
  // undamped has w = 2 pi: v spans 2 pi times u's range, so v's range sets
  // the pixels per unit and u's range widens about its middle.
  auto run = test::trajectory("undamped", {"steps_per_period=200", "periods=1"});
  const auto rows = test::rows(*run);
  const render::PixelRect outer{0, 0, 400, 300};
  scenes::PhasePanel panel(outer, 1, "<i>u</i>", "<i>v</i>",
                           {{"", render::palette::blue, [](std::span<const double> r) { return r[1]; },
                             [](std::span<const double> r) { return r[2]; }}},
                           run->info().mesh.period);
  panel.keep_equal_scales();
  for (const auto& row : rows) panel.record(row);
  panel.finish_recording();
  const render::Point origin = panel.pixel_of(0, 0), right = panel.pixel_of(1, 0), up = panel.pixel_of(0, 1);
  CHECK(right.x() - origin.x() == Approx(origin.y() - up.y()).epsilon(1e-12));
  const render::PixelRect area = render::PlotPanel(outer, 1).area();
  double top = 1e300, bottom = -1e300;
  for (const auto& row : rows) {
    const render::Point p = panel.pixel_of(row[1], row[2]);
    CHECK(p.x() >= area.x);
    CHECK(p.x() <= area.x + area.w);
    CHECK(p.y() >= area.y);
    CHECK(p.y() <= area.y + area.h);
    top = std::min(top, p.y()), bottom = std::max(bottom, p.y());
  }
  CHECK(bottom - top > 0.85 * area.h);  // the tall axis is filled, not shrunk
}
