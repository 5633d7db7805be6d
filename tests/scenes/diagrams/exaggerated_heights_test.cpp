// The bumpy road's --exaggerate F as drawn: road, wheel and body heights all
// F times larger, measured in a frame's recorded outline, with the wheel still on the road.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "core/models/model.hpp"
#include "render/draw/canvas.hpp"
#include "render/labels/drawing_record.hpp"
#include "scene_run_support.hpp"
#include "scenes/config/scene_config.hpp"
#include "scenes/scene_factory.hpp"

using vibra::render::OutlineKind;
using vibra::render::OutlineShape;
using vibra::render::PixelRect;

namespace {
/// What a frame of the bumpy road shows, in pixels (y down), and its row.
struct DrawnVehicle {
  std::vector<double> row;
  PixelRect wheel, body;            ///< the wheel's disc and the body's box, as filled
  std::vector<vibra::render::Point> road;  ///< the road's line in view
  double road_at_wheel = 0;                 ///< its pixel row under the wheel's centre
};

/// The road's line: the ground's outline without the corners that close it
/// at the bottom of the view (the outline may repeat its first point).
std::vector<vibra::render::Point> road_line(const std::vector<vibra::render::Point>& ground) {
  double bottom = -INFINITY;
  for (const auto& p : ground) bottom = std::max(bottom, p.y());
  std::vector<vibra::render::Point> road;
  for (const auto& p : ground)
    if (p.y() < bottom - 0.5 && (road.empty() || p.x() > road.back().x())) road.push_back(p);
  return road;
}

/// The road's pixel row at column x along its line.
double road_row_at(const std::vector<vibra::render::Point>& road, double x) {
  for (size_t i = 0; i + 1 < road.size(); ++i) {
    const auto &a = road[i], &b = road[i + 1];
    if (a.x() <= x && x <= b.x() && b.x() > a.x()) return a.y() + (b.y() - a.y()) * (x - a.x()) / (b.x() - a.x());
  }
  FAIL("the road's outline does not reach column " << x);
  return 0;
}

/// The frame at `moment` of the bumpy road on a sine road drawn with exaggerate = F.
DrawnVehicle draw_vehicle(double F, double moment) {
  vibra::scenes::SceneConfig config = vibra::scenes::load_scene("bumpy_road");
  for (const auto& [key, value] : std::vector<std::pair<std::string, std::string>>{
           {"road", "sine"}, {"A", "0.05"}, {"wavelength", "2"}, {"exaggerate", std::to_string(F)}})
    vibra::scenes::apply_setting(config, {key, value, "test"});
  config.width = 640, config.height = 360;
  long long steps = 0;
  auto scene = vibra::test::scene_after_pre_pass(config, steps);
  DrawnVehicle d;
  d.row = vibra::test::observed_row_at(*scene, config, steps, moment);
  vibra::render::Canvas canvas = vibra::render::Canvas::image(config.width, config.height);
  scene->draw(canvas, d.row);
  REQUIRE(scene->last_layout());
  const std::vector<vibra::render::Point>* ground = nullptr;
  for (const OutlineShape& s : scene->last_layout()->outline.shapes()) {
    if (s.kind == OutlineKind::ground && !s.polygons.empty()) ground = &s.polygons.front();
    if (s.kind != OutlineKind::body || s.half_width != 0 || s.polygons.empty()) continue;
    const bool round = std::abs(s.bounds.w - s.bounds.h) < 2;
    if (round && s.bounds.w > d.wheel.w) d.wheel = s.bounds;                 // the disc, not the hub
    if (!round && s.bounds.w > 2 * s.bounds.h && s.bounds.w > d.body.w) d.body = s.bounds;  // the body's box
  }
  REQUIRE(ground != nullptr);
  REQUIRE(d.wheel.w > 0);
  REQUIRE(d.body.w > 0);
  d.road = road_line(*ground);
  d.road_at_wheel = road_row_at(d.road, d.wheel.x + 0.5 * d.wheel.w);
  return d;
}
}  // namespace

TEST_CASE("exaggerate F: road, wheel and body heights drawn F times larger, the wheel on the road", "[scene][diagram]") {
  // The road is h(x) = A sin(2 pi x / wavelength), A = 0.05 m,
  // wavelength 2 m; the wheel has R = 0.3 m and the body rests L = 0.6 m over
  // the axle. The view follows the vehicle sideways only, so in pixels (y
  // down) every road point lies F h(x) - F h(x_wheel) above the road under the wheel.
  const double A = 0.05, wavelength = 2, R = 0.3, L = 0.6;
  const auto h = [&](double x) { return A * std::sin(2 * M_PI * x / wavelength); };
  for (double F : {1.0, 4.0})
    for (double moment : {0.3, 0.7}) {
      const DrawnVehicle d = draw_vehicle(F, moment);
      REQUIRE(d.row.size() >= 5);
      const double pixels_per_metre = d.wheel.h / (2 * R), u = d.row[1];
      const double axle = d.wheel.y + 0.5 * d.wheel.h, body_bottom = d.body.y + d.body.h;
      INFO("F = " << F << " at t = " << d.row[0] << ", u = " << u << ", h = " << d.row[4] << ": "
                  << pixels_per_metre << " px/m");
      INFO("the wheel's lowest point on the road (contact)");
      CHECK(std::abs(d.wheel.y + d.wheel.h - d.road_at_wheel) < 1.5);
      double worst = 0, x_wheel = d.row[3], centre = d.wheel.x + 0.5 * d.wheel.w;
      for (const auto& p : d.road) {
        const double x = x_wheel + (p.x() - centre) / pixels_per_metre;
        const double expected = -pixels_per_metre * F * (h(x) - h(x_wheel));
        worst = std::max(worst, std::abs(p.y() - d.road_at_wheel - expected));
      }
      INFO("the road drawn as F h(x) across the view (" << d.road.size() << " points)");
      CHECK(d.road.size() > 20);
      CHECK(worst < 1.5);
      INFO("the body's bottom over the axle is L + F u");
      CHECK((axle - body_bottom) / pixels_per_metre == Approx(L + F * u).margin(2 / pixels_per_metre));
    }
}
