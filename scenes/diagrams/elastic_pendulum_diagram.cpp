// The elastic pendulum's diagram (section 1.12.7): pivot, spring wire, bob and forces.
#include "scenes/diagrams/elastic_pendulum_diagram.hpp"

#include <cmath>

#include "render/draw/annotations.hpp"
#include "render/draw/elements/machine_elements.hpp"
#include "scenes/diagrams/forces/broken_force.hpp"
#include "scenes/diagrams/forces/drawn_force.hpp"
#include "scenes/diagrams/diagram_registry.hpp"
#include "scenes/diagrams/planar_row.hpp"

namespace vibra::scenes {

namespace {
const Point kPivot(0, 1);
constexpr double kLongestArrow = 0.45;
}  // namespace

ElasticPendulumDiagram::ElasticPendulumDiagram(double beta, double gamma, SceneColors colors)
    : beta_(beta), gamma_(gamma), colors_(colors) {
  bodies_.setEmpty();
}

std::vector<PanelSpec> ElasticPendulumDiagram::panels() const {
  return {{"<i>θ</i> (degrees)", {{"", colors_.bob, [](std::span<const double> r) { return r[5] * 180 / M_PI; }}}},
          {"<i>S</i> / <i>mg</i>  wire force",
           {{"", colors_.wire_force, [beta = beta_](std::span<const double> r) { return ((Point(r[1], r[2]) - kPivot).norm() - beta) / (1 - beta); }}}}};
}

double ElasticPendulumDiagram::wire_force(std::span<const double> row) const {
  const double L = (planar_position(row) - kPivot).norm();
  return (L - beta_) / (1 - beta_);
}

void ElasticPendulumDiagram::record(std::span<const double> row, WorldBox& world) {
  trail_.add(row[0], planar_position(row));
  record_other(row, world);
}

void ElasticPendulumDiagram::record_other(std::span<const double> row, WorldBox&) {
  bodies_.extend(planar_position(row));
  support_.see(planar_position(row), kBob);
  scale_.see(1);
  scale_.see(wire_force(row));
  scale_.see(gamma_ / (beta_ * beta_) * planar_velocity(row).squaredNorm());
}

void ElasticPendulumDiagram::finish_recording(WorldBox& world) {
  // mg = 1 reads at any scale; a wire force far larger is drawn clipped.
  scale_.set_reference(1);
  scale_.set_longest(kLongestArrow);
  // The bob's reach, every arrow from anywhere it goes, the ceiling.
  const Point reach(kBob + kLongestArrow + 0.08, kBob + kLongestArrow + 0.08);
  if (!bodies_.isEmpty()) world.extend(bodies_.min() - reach), world.extend(bodies_.max() + reach);
  world.extend(kPivot + Point(0.35, 0.12));
  world.extend(kPivot - Point(0.35, 0));
  center_horizontally_on(world, kPivot.x());  // the pivot on the frame's centre line
}

std::array<Arrow, 3> ElasticPendulumDiagram::force_arrows(std::span<const double> row) const {
  const Point p = planar_position(row), v = planar_velocity(row);
  const Point toward_pivot = (kPivot - p).normalized();
  const double per = scale_.per_force();
  const Point drag = -gamma_ / (beta_ * beta_) * v.norm() * v;
  return {Arrow{p, p + Point(0, -per)}, Arrow{p, p + per * wire_force(row) * toward_pivot}, Arrow{p, p + per * drag}};
}

void ElasticPendulumDiagram::draw_static(render::Canvas& canvas, const render::WorldView& view) const {
  support_.draw(canvas, view, colors_.wire);
}

void ElasticPendulumDiagram::draw(render::Canvas& canvas, const render::WorldView& view, std::span<const double> row) {
  const Point p = planar_position(row);
  trail_.draw(canvas, view, row[0], kFade, colors_.bob, 1.8, p);
  render::SpringShape spring;
  spring.width = 0.07, spring.lead = 0.08, spring.coils = 12;
  render::draw_spring(canvas, view, kPivot, p + kBob * (kPivot - p).normalized(), spring, {colors_.wire, 1.8});
  render::draw_circle(canvas, view, p, kBob, colors_.bob, {colors_.wire, 1.6});
  if (ghost()) return;
  auto arrows = force_arrows(row);
  for (Arrow& a : arrows) a = from_rim(a.from, kBob + rim_gap(canvas, view), a.to);
  render::ForceArrow forces[] = {{arrows[0].from, arrows[0].to, colors_.gravity, "<i>mg</i>"},
                                       {arrows[1].from, arrows[1].to, colors_.wire_force, "<i>S</i>"},
                                       {arrows[2].from, arrows[2].to, colors_.drag, "<i>D</i>"}};
  // Without drag (gamma = 0) a ring labelled D would claim a force the model does not have.
  for (auto& f : forces) {
    f.from_rim = true;
    if (&f != &forces[2] || gamma_ > 0) draw_broken_force(canvas, view, scale_.longest(), f, colors_.background);
  }
}

std::optional<ForceKey> ElasticPendulumDiagram::force_key() const {
  std::vector<ForceName> names = {{colors_.gravity, "<i>mg</i> gravity"}, {colors_.wire_force, "<i>S</i> wire (spring) force"}};
  if (gamma_ > 0) names.push_back({colors_.drag, "<i>D</i> air drag"});
  return ForceKey{scale_.per_force(), "<i>mg</i>", "", names};
}

DiagramKind elastic_pendulum_diagram_kind() {
  return {"elastic_pendulum",
          "pendulum on an elastic wire drawn as a stretching spring, the bob's fading path, arrows mg, S and drag D "
          "(section 1.12.7)",
          {"elastic-pendulum"}, [](const DiagramInput& in) {
            return std::make_unique<ElasticPendulumDiagram>(in.parameters.number("beta"), in.parameters.number("gamma"),
                                                            in.config.colors);
          }};
}

}  // namespace vibra::scenes
