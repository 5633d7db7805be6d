// The pendulum's free-body diagram: support, wire, bob, forces and the angle.
#include "scenes/panels/plot_panels.hpp"
#include "scenes/diagrams/pendulum/pendulum_diagram.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "render/draw/annotations.hpp"
#include "render/draw/elements/shapes.hpp"
#include "render/draw/text.hpp"
#include "render/labels/label_placer.hpp"
#include "scenes/diagrams/forces/broken_force.hpp"
#include "scenes/diagrams/forces/drawn_force.hpp"
#include "scenes/diagrams/diagram_registry.hpp"

namespace vibra::scenes {

using render::Canvas;
using render::Color;
using render::TextStyle;

namespace {
std::string magnification_label(double m) {
  if (m == 1) return "<i>D</i>";
  char text[64];
  std::snprintf(text, sizeof text, m == std::round(m) ? "%.0f" : "%g", m);
  return std::string("<i>D</i> \u00d7") + text;
}

PendulumState state_of(std::span<const double> row) { return {row[0], row[1], row[2], row[3], row[4]}; }
}  // namespace

PendulumDiagram::PendulumDiagram(PendulumDiagramOptions options, SceneColors colors)
    : options_(options), colors_(colors) {}

std::vector<PanelSpec> PendulumDiagram::panels() const {
  auto column = [](int i, double factor) { return [i, factor](std::span<const double> row) { return factor * row[i]; }; };
  // theta is shown in degrees, the forces in units of m g.
  return {{quantity_markup("theta"), {{"", colors_.bob, column(1, display_factor("theta"))}}},
          // Built before the pre-pass has seen S's sign: from the swing's bound.
          {options_.link_may_push ? "<i>S</i> / <i>mg</i>  wire force (&lt; 0: a rod, pushing)"
                                  : "<i>S</i> / <i>mg</i>  wire force",
           {{"", colors_.wire_force, column(3, 1)}}},
          {"<i>D</i> / <i>mg</i>  air drag", {{"", colors_.drag, column(4, 1)}}}};
}

void PendulumDiagram::record(std::span<const double> row, WorldBox& world) {
  const PendulumGeometry g = pendulum_geometry(state_of(row), options_);
  const double r = options_.bob_radius;
  support_.see(g.bob, r);
  if (row[4] != 0) has_drag_ = true;
  if (row[3] < 0) pushed_ = true;
  // S > 0 points from the bob toward the pivot, inside the bob's circle,
  // where it has the wire's length for room (kInwardRoom), not the margin's.
  scale_.see(row[3] > 0 ? row[3] * kArrowRoom / kInwardRoom : row[3]);
  scale_.see(options_.drag_magnification * row[4]);
  // The view is set by the bob's motion and the room its arrows get
  // (kArrowRoom, longer ones drawn clipped), not by the arrows' lengths.
  const Point room = Point::Constant(std::max(r, kArrowRoom));  // arrows start at the bob's centre
  world.extend(g.bob + room), world.extend(g.bob - room);
  if (options_.geometry) world.extend(g.radial_unit_tip), world.extend(g.azimuthal_unit_tip);
}

void PendulumDiagram::finish_recording(WorldBox& world) {
  // mg = 1 is the reference every run's scale draws readably.
  scale_.see(1);
  scale_.set_reference(1);
  scale_.set_longest(kArrowRoom);
  options_.force_unit = scale_.per_force();
  // The ceiling, the dashed vertical and the angle label always fit; the
  // pivot on the frame's centre line.
  world.extend(Point(-0.35, 0.12));
  world.extend(Point(0.35, -options_.vertical_length));
  center_horizontally_on(world, 0);
}

void PendulumDiagram::draw_static(Canvas& canvas, const render::WorldView& view) const {
  support_.draw(canvas, view, colors_.wire);
}

void PendulumDiagram::draw(Canvas& canvas, const render::WorldView& view, std::span<const double> row) {
  const PendulumState state = state_of(row);
  const auto& o = options_;
  const auto& c = colors_;
  const PendulumGeometry g = pendulum_geometry(state, o);
  const double scale = canvas.scale();

  if (ghost()) {
    draw_link(canvas, view, g);
    draw_circle(canvas, view, g.bob, o.bob_radius, c.bob, {c.wire, 1.6});
    return;
  }
  draw_line(canvas, view, g.pivot, g.vertical_end, {c.wire.with_alpha(0.6), 1.6, true});
  draw_link(canvas, view, g);
  draw_arc(canvas, view, g.pivot, o.arc_radius, g.arc_from, g.arc_to, {c.wire, 1.6});
  draw_circle(canvas, view, g.bob, o.bob_radius, c.bob, {c.wire, 1.6});

  // S runs along the wire toward the pivot, where a label beyond its tip
  // would sit on the wire and the angle arc: it goes beside the shaft instead,
  // away from the vertical and the arc.
  const Point outward(std::cos(state.theta), -std::sin(state.theta));  // i_theta in pixels (y down)
  const double side = state.theta >= 0 ? 1 : -1;
  const double rim = o.bob_radius + rim_gap(canvas, view);
  const Arrow mg = from_rim(g.bob, rim, g.gravity_tip), S = from_rim(g.bob, rim, g.wire_force_tip),
              D = from_rim(g.bob, rim, g.drag_tip);
  render::ForceArrow forces[] = {
      {mg.from, mg.to, c.gravity, "<i>mg</i>"},
      {S.from, S.to, c.wire_force, state.S < 0 ? "<i>S</i> push" : "<i>S</i>", render::LabelPlace::beside,
       side * outward},
      {D.from, D.to, c.drag, magnification_label(o.drag_magnification)}};
  // Without drag (alpha = 0) there is no D to draw: a ring labelled D would
  // claim a force the model does not have.
  // Each arrow is clipped at its room: S toward the pivot has the wire's.
  const double rooms[] = {kArrowRoom, state.S > 0 ? kInwardRoom : kArrowRoom, kArrowRoom};
  for (int i = 0; i < 3; ++i) {
    forces[i].from_rim = true;
    if (i != 2 || has_drag_) draw_broken_force(canvas, view, rooms[i], forces[i], c.background);
  }

  // The angle's label beyond the middle of its arc, placed like the arrows' labels.
  if (std::abs(state.theta) > 0.02) {
    TextStyle label{24, c.wire};
    label.halo = true, label.halo_color = c.background;
    const Point at = view.to_pixel(g.pivot + o.arc_radius * g.theta_label_direction);
    const Point direction(g.theta_label_direction.x(), -g.theta_label_direction.y());
    render::request_label(canvas, {"<i>θ</i>", label, at, direction, 4 * scale});
  }
  if (o.geometry) draw_geometry(canvas, view, g, side * outward);
}

void PendulumDiagram::draw_link(Canvas& canvas, const render::WorldView& view, const PendulumGeometry& g) const {
  if (!pushed_) {
    draw_line(canvas, view, g.pivot, g.bob, {colors_.wire, 2.2});
    return;
  }
  // A strut: a hollow bar, thick enough to push, unlike a wire.
  draw_line(canvas, view, g.pivot, g.bob, {colors_.wire, 6.5});
  draw_line(canvas, view, g.pivot, g.bob, {colors_.background, 2.5});
}

void PendulumDiagram::draw_geometry(Canvas& canvas, const render::WorldView& view, const PendulumGeometry& g,
                                    const Point& away_from_vertical) const {
  // Fig 1.21's geometry: the bob is at r = x0 i + y0 j + L i_r, with
  // i_r = sin(theta) i - cos(theta) j and i_theta = cos(theta) i + sin(theta) j.
  const auto& c = colors_;
  const double scale = canvas.scale();
  const render::ForceArrow vectors[] = {
      {g.unit_origin, g.radial_unit_tip, c.wire, "<b>i</b><sub><i>r</i></sub>"},
      {g.unit_origin, g.azimuthal_unit_tip, c.wire, "<b>i</b><sub><i>θ</i></sub>"}};
  for (const auto& v : vectors) draw_force_arrow(canvas, view, v, c.background);
  TextStyle label{22, c.wire};
  label.halo = true, label.halo_color = c.background;
  // The pivot's coordinates beside it, away from the bob; L beside the
  // wire's middle on the side of the vertical, where no arrow runs.
  const Point pivot = view.to_pixel(g.pivot);
  const Point bob_side = view.to_pixel(g.bob) - pivot;
  const Point away_from_bob = Point(bob_side.x() > 0 ? -1 : 1, 0.6).normalized();
  render::request_label(canvas, {"(<i>x</i><sub>0</sub>, <i>y</i><sub>0</sub>)", label, pivot, away_from_bob, 8 * scale});
  render::request_label(canvas, {"<i>L</i>", label, view.to_pixel(0.5 * (g.pivot + g.bob)), -away_from_vertical,
                                 4 * scale});
}

std::optional<ForceKey> PendulumDiagram::force_key() const {
  // magnification_label gives "<i>D</i> ×5": the key says "<i>D</i> drawn ×5".
  std::string note;
  if (has_drag_ && options_.drag_magnification != 1)
    note = magnification_label(options_.drag_magnification).insert(8, " drawn");
  std::vector<ForceName> names = {{colors_.gravity, "<i>mg</i> gravity"},
                                  {colors_.wire_force, pushed_ ? "<i>S</i> rod force (a strut: pushes when <i>S</i> &lt; 0)"
                                                               : "<i>S</i> wire force"}};
  if (has_drag_) names.push_back({colors_.drag, "<i>D</i> air drag"});
  return ForceKey{options_.force_unit, "<i>mg</i>", note, names};
}

DiagramKind pendulum_diagram_kind() {
  return {"pendulum", "free-body diagram of the pendulum: wire, bob, angle arc, arrows mg, S and the magnified drag D",
          {"pendulum", "physical-pendulum"}, [](const DiagramInput& in) {
            PendulumDiagramOptions options;
            options.drag_magnification = in.config.drag_magnification;
            // Energy bounds the swing (drag only lowers it): within 90 degrees
            // S = omega^2 + cos(theta) > 0 throughout. A bound of 0 is over the top.
            const double bound = in.info.amplitude_bound;
            options.link_may_push = !(bound > 0 && bound <= M_PI / 2);
            options.geometry = std::find(in.config.annotate.begin(), in.config.annotate.end(), "geometry") !=
                               in.config.annotate.end();
            return std::make_unique<PendulumDiagram>(options, in.config.colors);
          },
          {"geometry"}};
}

}  // namespace vibra::scenes
