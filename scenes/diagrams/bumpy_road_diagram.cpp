// The bumpy road's diagram (section 1.12.8): road, wheel, spring, dashpot and body.
#include "scenes/diagrams/bumpy_road_diagram.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/models/model.hpp"
#include "render/draw/annotations.hpp"
#include "render/draw/elements/ground_profile.hpp"
#include "render/draw/elements/machine_elements.hpp"
#include "scenes/diagrams/diagram_registry.hpp"

namespace vibra::scenes {

BumpyRoadDiagram::BumpyRoadDiagram(std::shared_ptr<const RoadProfile> road, Vehicle vehicle, SceneColors colors,
                                   double exaggerate)
    : road_(std::move(road)), vehicle_(vehicle), colors_(colors), requested_(exaggerate) {
  body_width_ = 3.2 * vehicle_.R, body_height_ = 0.9 * vehicle_.R;
  half_width_ = 1.4 * (vehicle_.R + vehicle_.L + body_height_);
}

std::vector<PanelSpec> BumpyRoadDiagram::panels() const {
  auto column = [](int i) { return [i](std::span<const double> r) { return r[i]; }; };
  PanelSpec forces{"forces on the body (N)", {}};
  forces.series.push_back({"spring −<i>ku</i>", colors_.gravity, [k = vehicle_.k](std::span<const double> r) { return -k * r[1]; }});
  if (vehicle_.b > 0)
    forces.series.push_back({"damper −<i>bu</i>′", colors_.drag, [b = vehicle_.b](std::span<const double> r) { return -b * r[2]; }});
  return {{"<i>u</i> (m)  body over the axle, from rest", {{"", colors_.bob, column(1)}}},
          {"road <i>h</i>(<i>st</i>) (m)", {{"", colors_.wire, column(4)}}},
          std::move(forces)};
}

void BumpyRoadDiagram::record(std::span<const double> row, WorldBox&) {
  scale_.see(vehicle_.k * row[1]);
  scale_.see(vehicle_.b * row[2]);
  lowest_road_ = std::min(lowest_road_, row[4]);
  highest_road_ = std::max(highest_road_, row[4]);
  highest_top_ = std::max(highest_top_, row[4] + row[1]);  // the body's top is F (h + u) + R + L + its height
  swing_ = std::max(swing_, std::abs(row[1]));
}

double BumpyRoadDiagram::automatic_exaggeration(double swing, double bumps, const Vehicle& v) {
  if (swing >= v.L / 7 || !(swing > 0)) return 1;
  double best = 1;
  for (double decade = 1; decade <= 1000; decade *= 10)
    for (double m : {1, 2, 3, 4, 5})
      if (m * decade * swing <= 0.5 * v.L && m * decade * bumps <= 0.8 * v.R) best = std::max(best, m * decade);
  return best;
}

void BumpyRoadDiagram::finish_recording(WorldBox& world) {
  scale_.set_longest(0.9 * vehicle_.L);
  const double reach = scale_.length(scale_.largest());
  factor_ = requested_ > 0 ? requested_
                           : automatic_exaggeration(swing_, highest_road_ - lowest_road_, vehicle_);
  low_ = factor_ * lowest_road_ - 0.35 * vehicle_.R;
  high_ = factor_ * highest_top_ + vehicle_.R + vehicle_.L + body_height_;
  high_ += std::max(0.4 * vehicle_.R, reach - 0.5 * body_height_ + 0.3 * vehicle_.R);
  world.extend(Point(-half_width_, low_));
  world.extend(Point(half_width_, high_));
  // The ground reaches below the view: a pale band under the road, hatched.
  ground_.emplace([road = road_, f = factor_](double s) { return f * road->height(s); }, road_->dx(),
                  0.3 * vehicle_.R + (high_ - low_),
                  render::Stroke{colors_.wire, 2.2});
}

std::optional<FollowingView> BumpyRoadDiagram::view_at(std::span<const double> row) const {
  return FollowingView{Point(row[3], 0.5 * (low_ + high_)), Point(2 * half_width_, high_ - low_)};
}

std::vector<DrawnForce> BumpyRoadDiagram::forces(std::span<const double> row) const {
  // Vertical, from the body's centre line: the spring's at the left, the damper's (only with b > 0) at the right.
  const Point c(row[3], body_bottom(row) + 0.5 * body_height_);
  const double dx = 0.28 * body_width_;
  std::vector<DrawnForce> out = {
      {ForceKind::spring, {c - Point(dx, 0), c + Point(-dx, scale_.length(-vehicle_.k * row[1]))}, colors_.gravity,
       "−<i>ku</i>"}};
  if (vehicle_.b > 0)
    out.push_back({ForceKind::damper, {c + Point(dx, 0), c + Point(dx, scale_.length(-vehicle_.b * row[2]))},
                   colors_.drag, "−<i>bu</i>′"});
  return out;
}

void BumpyRoadDiagram::draw(render::Canvas& canvas, const render::WorldView& view, std::span<const double> row) {
  const double x = row[3];
  const render::Stroke ink{colors_.wire, 2.2};
  // The road across the visible part (the scene clips it to the diagram's area).
  if (!ghost()) ground_->draw(canvas, view);

  const Point a = axle(row);
  const double bottom = body_bottom(row);
  // The wheel first: the axle's bar, the spring and the damper go over it.
  render::draw_wheel(canvas, view, a, vehicle_.R, wheel_turn(x), colors_.background, {colors_.wire, 2});
  render::SpringShape spring;
  spring.width = 0.45 * vehicle_.R, spring.lead = 0.18 * vehicle_.L, spring.coils = 6;
  const double strut = strut_offset();
  render::draw_spring(canvas, view, a + Point(-strut, 0), Point(x - strut, bottom), spring, ink);
  render::DashpotShape dashpot;
  dashpot.width = 0.4 * vehicle_.R, dashpot.rest_length = vehicle_.L, dashpot.cylinder = 0.45;
  render::draw_dashpot(canvas, view, a + Point(strut, 0), Point(x + strut, bottom), dashpot, ink);
  render::draw_line(canvas, view, a + Point(-strut, 0), a + Point(strut, 0), {colors_.wire, 3});
  render::draw_box(canvas, view, Point(x - 0.5 * body_width_, bottom), Point(x + 0.5 * body_width_, bottom + body_height_),
                   colors_.bob.with_alpha(0.85), {colors_.wire, 1.8});
  if (ghost()) return;

  for (const DrawnForce& f : forces(row))
    render::draw_force_arrow(canvas, view, {f.arrow.from, f.arrow.to, f.color, f.label}, colors_.background);
}

std::optional<ForceKey> BumpyRoadDiagram::force_key() const {
  char note[64] = "";
  if (factor_ != 1) std::snprintf(note, sizeof note, "heights drawn ×%g", factor_);
  // u is measured from the rest height, where the spring's static load
  // carries the weight: the two cancel, and the name says why neither is drawn.
  std::vector<ForceName> names = {{colors_.gravity, "−<i>ku</i> spring beyond its static load"}};
  if (vehicle_.b > 0) names.push_back({colors_.drag, "−<i>bu</i>′ damper"});
  return ForceKey{scale_.per_force(), "N", note, names};
}

DiagramKind bumpy_road_diagram_kind() {
  return {"bumpy_road", "vehicle on a bumpy road: road profile, rolling wheel, spring and damper, view following (section 1.12.8)",
          {"bumpy-road"}, [](const DiagramInput& in) {
            const Parameters& p = in.parameters;
            const double distance = p.number("speed") * in.info.mesh.T;
            auto road = std::make_shared<const RoadProfile>(road_of(p, distance + 2 * p.positive("wavelength")));
            return std::make_unique<BumpyRoadDiagram>(
                road, BumpyRoadDiagram::Vehicle{p.number("k"), p.number("b"), p.number("R"), p.number("L")},
                in.config.colors, in.config.exaggerate);
          },
          {},
          true};
}

}  // namespace vibra::scenes
