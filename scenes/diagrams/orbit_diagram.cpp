// The two-body orbit's diagram (section 1.12.10): star, planet and trail.
#include "scenes/diagrams/orbit_diagram.hpp"

#include "render/draw/annotations.hpp"
#include "render/draw/elements/shapes.hpp"
#include "scenes/diagrams/diagram_registry.hpp"
#include "scenes/diagrams/planar_row.hpp"
#include "scenes/config/scene_config.hpp"

namespace vibra::scenes {

namespace {
constexpr double kStar = 0.09, kPlanet = 0.045, kLongestOrbitArrow = 0.45;
Point gravity(std::span<const double> row) {
  const Point x = planar_position(row);
  const double r = x.norm();
  return -x / (r * r * r);
}
}  // namespace

OrbitDiagram::OrbitDiagram(double window, double t_end, SceneColors colors)
    : window_(window), t_end_(t_end), colors_(colors) {
  bodies_.setEmpty();
}

std::vector<PanelSpec> OrbitDiagram::panels() const {
  // x and y, and the distance's drift from its start, where a circular
  // orbit shows its scheme: at 200 steps an orbit Euler-Cromer's radius
  // swings by 1e-2, PEFRL's by 2e-8 (the axis states the power of ten once). The panels sample rows
  // after record() has seen the first one.
  const auto radius_drift = [this](std::span<const double> r) { return planar_position(r).norm() - start_radius_; };
  return {{"<i>x</i>", {{"", colors_.bob, [](std::span<const double> r) { return r[1]; }}}},
          {"<i>y</i>", {{"", colors_.bob, [](std::span<const double> r) { return r[2]; }}}},
          {"<i>r</i> − <i>r</i>(0)", {{"", colors_.bob, radius_drift}}}};
}

void OrbitDiagram::record(std::span<const double> row, WorldBox& world) {
  if (first_) {
    // Circular when the speed is the circular one, 1/sqrt(r), across the radius.
    const Point x = planar_position(row), v = planar_velocity(row);
    const double r = x.norm();
    start_radius_ = r;
    if (r > 0 && std::abs(x.dot(v)) < 1e-12 * r * v.norm() && std::abs(v.squaredNorm() * r - 1) < 1e-12)
      circle_radius_ = r;
    first_ = false;
  }
  trail_.add(row[0], planar_position(row));
  record_other(row, world);
}

void OrbitDiagram::record_other(std::span<const double> row, WorldBox&) {
  bodies_.extend(planar_position(row));
  gravity_.see(gravity(row).norm());
  speed_.see(planar_velocity(row).norm());
}

void OrbitDiagram::finish_recording(WorldBox& world) {
  gravity_.set_longest(kLongestOrbitArrow);
  speed_.set_longest(kLongestOrbitArrow);
  const Point reach(kLongestOrbitArrow + 0.12, kLongestOrbitArrow + 0.12);
  if (!bodies_.isEmpty()) world.extend(bodies_.min() - reach), world.extend(bodies_.max() + reach);
  world.extend(Point(-kStar - 0.1, -kStar - 0.1));
  world.extend(Point(kStar + 0.1, kStar + 0.1));
  world.extend(Point(-circle_radius_, -circle_radius_));
  world.extend(Point(circle_radius_, circle_radius_));
}

std::array<Arrow, 2> OrbitDiagram::arrows(std::span<const double> row) const {
  const Point x = planar_position(row), v = planar_velocity(row);
  return {Arrow{x, x + gravity_.per_force() * gravity(row)}, Arrow{x, x + speed_.per_force() * v}};
}

void OrbitDiagram::draw_static(render::Canvas& canvas, const render::WorldView& view) const {
  if (circle_radius_ > 0)
    render::draw_arc(canvas, view, Point::Zero(), circle_radius_, 0, 2 * M_PI, {colors_.wire.with_alpha(0.55), 1.4, true});
  render::draw_circle(canvas, view, Point::Zero(), kStar, render::palette::orange, {colors_.wire, 1.4});
}

void OrbitDiagram::draw(render::Canvas& canvas, const render::WorldView& view, std::span<const double> row) {
  // Without a window the whole run's path stays, fading only slightly.
  const Point x = planar_position(row);
  trail_.draw(canvas, view, row[0], window_ > 0 ? window_ : 2 * t_end_ + 1, colors_.bob, 1.6, x);
  render::draw_circle(canvas, view, x, kPlanet, colors_.bob, {colors_.wire, 1.4});
  if (ghost()) return;
  const auto a = arrows(row);
  render::draw_force_arrow(canvas, view, {a[0].from, a[0].to, colors_.gravity, "<i>F</i>"}, colors_.background);
  render::draw_force_arrow(canvas, view, {a[1].from, a[1].to, colors_.wire_force, "<i>v</i>"}, colors_.background);
}

DiagramKind orbit_diagram_kind() {
  return {"orbit",
          "planet around a star: its trail (the last orbits with --window), the exact circle dashed, arrows for "
          "gravity and velocity (section 1.12.10)",
          {"two-body"}, [](const DiagramInput& in) {
            return std::make_unique<OrbitDiagram>(window_width(in.config, in.info.mesh.period), in.info.mesh.T,
                                                  in.config.colors);
          }};
}

}  // namespace vibra::scenes
