#include "scenes/diagrams/sliding_box_diagram.hpp"

#include <cmath>
#include <cstdio>

#include "render/draw/annotations.hpp"
#include "render/draw/machine_elements.hpp"
#include "scenes/diagrams/diagram_registry.hpp"
#include "scenes/panels/plot_panels.hpp"

namespace vibra::scenes {

SlidingBoxDiagram::SlidingBoxDiagram(SlidingBoxLaw law, std::function<double(double)> exact, SceneColors colors)
    : law_(law), exact_(std::move(exact)), colors_(colors) {}

std::vector<PanelSpec> SlidingBoxDiagram::panels() const {
  PanelSpec u{"<i>u</i>", {{"numerical", colors_.bob, [](std::span<const double> r) { return r[1]; }}}};
  if (exact_) u.series.push_back({"exact", colors_.gravity, [e = exact_](std::span<const double> r) { return e(r[0]); }, true});
  PanelSpec v{quantity_markup("v"), {{"", colors_.bob, [](std::span<const double> r) { return r[2]; }}}};
  PanelSpec f{"friction <i>f</i>", {{"", colors_.drag, [law = law_](std::span<const double> r) {
                                       return law.friction(r[1], r[2]);
                                     }}}};
  return {std::move(u), std::move(v), std::move(f)};
}

void SlidingBoxDiagram::record(std::span<const double> row, WorldBox&) {
  largest_u_ = std::max(largest_u_, std::abs(row[1]));
  scale_.see(law_.spring(row[1]));
  scale_.see(law_.friction(row[1], row[2]));
}

namespace {
/// The smallest of 1, 2, 5, 10, 20, 50, ... that draws `small` at least 40% as long as `large`.
double magnification_for(double small, double large) {
  if (!(small > 0) || small >= 0.4 * large) return 1;
  for (double decade = 1;; decade *= 10)
    for (double m : {1.0, 2.0, 5.0})
      if (m * decade * small >= 0.4 * large || m * decade >= 1e6) return m * decade;
}
}  // namespace

void SlidingBoxDiagram::finish_recording(WorldBox& world) {
  layout_.emplace(largest_u_, false);
  scale_.set_longest(1.1 * layout_->unit);
  friction_magnification_ = magnification_for(law_.mu, scale_.largest());
  world.extend(layout_->extent());
  world.extend(Point(layout_->equilibrium_x() + 2.3 * layout_->unit, 0));
  world.extend(Point(layout_->equilibrium_x(), -0.75 * layout_->unit));  // the normal force's label under the floor
}

std::array<Arrow, 2> SlidingBoxDiagram::force_arrows(std::span<const double> row) const {
  const double u = row[1], v = row[2];
  const Point c = layout_->body_center(u);
  const Point foot(c.x() - 0.2 * layout_->body_width, 0.02 * layout_->unit);
  return {Arrow{c, c + Point(scale_.length(-law_.spring(u)), 0)},
          Arrow{foot, foot + Point(friction_magnification_ * scale_.length(law_.friction(u, v)), 0)}};
}

void SlidingBoxDiagram::draw_static(render::Canvas& canvas, const render::WorldView& view) const {
  const HorizontalLayout& l = *layout_;
  const render::Stroke ink{colors_.wire, 2.2};
  render::draw_hatched_surface(canvas, view, Point(0, 0), Point(0, l.wall_height), Point(-1, 0), ink);
  render::draw_hatched_surface(canvas, view, Point(-0.3 * l.unit, 0), Point(l.equilibrium_x() + 2.3 * l.unit, 0),
                               Point(0, -1), ink);
  render::draw_line(canvas, view, Point(l.equilibrium_x(), 0),
                    Point(l.equilibrium_x(), l.body_height + 0.55 * l.unit), {colors_.wire.with_alpha(0.5), 1.4, true});
}

void SlidingBoxDiagram::draw(render::Canvas& canvas, const render::WorldView& view, std::span<const double> row) {
  const HorizontalLayout& l = *layout_;
  const double u = row[1], v = row[2];
  const render::Stroke ink{colors_.wire, 2.2};
  const double left = l.body_left(u);
  render::SpringShape spring;
  spring.width = 0.28 * l.unit, spring.lead = 0.18 * l.unit, spring.coils = 9;
  render::draw_spring(canvas, view, Point(0, l.height_at(0.5)), Point(left, l.height_at(0.5)), spring, ink);
  render::draw_box(canvas, view, Point(left, 0), Point(left + l.body_width, l.body_height),
                   colors_.bob.with_alpha(0.85), {colors_.wire, 1.8});
  if (ghost()) return;
  render::draw_dimension(canvas, view, Point(l.equilibrium_x(), l.body_height + 0.35 * l.unit),
                         Point(l.equilibrium_x() + u, l.body_height + 0.35 * l.unit), "<i>u</i>", Point(0, -1),
                         colors_.wire, colors_.background);

  // Weight and normal force: equal and opposite, a fixed length (see the class
  // comment); the normal force pushes up on the box's bottom from the floor.
  const Point c = l.body_center(u);
  const double x_weight = c.x() + 0.2 * l.body_width, x_normal = c.x() + 0.38 * l.body_width;
  render::draw_force_arrow(canvas, view, {Point(x_weight, c.y()), Point(x_weight, c.y() - 0.42 * l.body_height),
                                          colors_.wire_force, "<i>mg</i>", render::LabelPlace::beside, Point(-1, 0)},
                           colors_.background);
  render::draw_force_arrow(canvas, view, {Point(x_normal, -0.42 * l.body_height), Point(x_normal, 0), colors_.wire_force,
                                          "<i>N</i>", render::LabelPlace::beside, Point(1, 0)}, colors_.background);
  const auto arrows = force_arrows(row);
  render::draw_force_arrow(canvas, view, {arrows[0].from, arrows[0].to, colors_.gravity, "−<i>s</i>(<i>u</i>)"},
                           colors_.background);
  char magnified[32] = "";
  if (friction_magnification_ != 1) std::snprintf(magnified, sizeof magnified, " \u00d7%g", friction_magnification_);
  const std::string label = std::string("<i>f</i>") + magnified + (v != 0 ? " kinetic" : " static");
  render::draw_force_arrow(canvas, view, {arrows[1].from, arrows[1].to, colors_.drag, label, render::LabelPlace::beside,
                                          Point(0, 1)}, colors_.background);
}

std::optional<ForceKey> SlidingBoxDiagram::force_key() const {
  // mg and N are drawn at a fixed length: the key says so.
  std::string note = "<i>mg</i>, <i>N</i> not to scale";
  if (friction_magnification_ != 1) {
    char magnified[64];
    std::snprintf(magnified, sizeof magnified, "<i>f</i> drawn \u00d7%g, ", friction_magnification_);
    note = magnified + note;
  }
  return ForceKey{scale_.per_force(), "", note,
                  {{colors_.gravity, "−<i>s</i>(<i>u</i>) spring"}, {colors_.drag, "<i>f</i> friction"},
                   {colors_.wire_force, "<i>mg</i>, <i>N</i> weight, floor"}}};
}

DiagramKind sliding_box_diagram_kind() {
  return {"sliding_box",
          "box sliding on a floor with Coulomb friction, spring to the wall; kinetic or static friction (section 1.12.3)",
          {"sliding-box"}, [](const DiagramInput& in) {
            SlidingBoxLaw law;
            law.mu = in.parameters.number("mu"), law.alpha = in.parameters.number("alpha");
            return std::make_unique<SlidingBoxDiagram>(law, in.info.exact, in.config.colors);
          }};
}

}  // namespace vibra::scenes
