// The sliding box's diagram (section 1.12.3): box on a floor, spring to the wall, spring and friction forces.
#include "scenes/diagrams/sliding_box_diagram.hpp"

#include <cmath>
#include <cstdio>

#include "render/draw/annotations.hpp"
#include "render/draw/elements/machine_elements.hpp"
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
  for (ForceKind kind : present(row)) seen_.see(kind);
}

SlidingBoxDiagram::Phase SlidingBoxDiagram::phase(std::span<const double> row) const {
  if (row[2] != 0) return Phase::sliding;
  return law_.holds(row[1]) ? Phase::stuck : Phase::turning;
}

std::vector<ForceKind> SlidingBoxDiagram::present(std::span<const double> row) const {
  std::vector<ForceKind> kinds = {ForceKind::weight, ForceKind::normal};
  if (law_.spring(row[1]) != 0) kinds.push_back(ForceKind::spring);
  if (law_.mu > 0 && law_.friction(row[1], row[2]) != 0) kinds.push_back(ForceKind::friction);
  return kinds;
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
  world.extend(Point(layout_->equilibrium_x(), -0.75 * layout_->unit));  // the labels of N and f under the floor
}

namespace {
/// Box heights: mg's and N's fixed length, short of the spring's arrow head at mid-height.
constexpr double kVertical = 0.34;
/// What the friction's label says in each phase (the model's mu is both the
/// kinetic and the static coefficient, section 1.12.3).
constexpr const char* kFrictionPhase[] = {" kinetic = μ<i>N</i>", " static ≤ μ<i>N</i>", " = μ<i>N</i> at the turn"};
/// Pixel side of a label beside its shaft (y down): N's at the left, mg's at
/// the right, the friction's under the floor; the spring's goes past its tip.
Point label_side(ForceKind kind) {
  return kind == ForceKind::normal ? Point(-1, 0) : kind == ForceKind::weight ? Point(1, 0) : Point(0, 1);
}
}  // namespace

std::vector<DrawnForce> SlidingBoxDiagram::forces(std::span<const double> row) const {
  const HorizontalLayout& l = *layout_;
  const double u = row[1], v = row[2];
  const Point c = l.body_center(u);
  // The floor's push on the box, N up and f along, from one point of the contact.
  const Point foot(c.x() - 0.2 * l.body_width, 0);
  std::vector<DrawnForce> out;
  for (ForceKind kind : present(row)) switch (kind) {
      case ForceKind::spring:
        out.push_back({kind, {c, c + Point(scale_.length(-law_.spring(u)), 0)}, colors_.gravity, "−<i>s</i>(<i>u</i>)"});
        break;
      case ForceKind::friction: {  // along the floor, just above its line
        const Point from = foot + Point(0, 0.02 * l.unit);
        char magnified[32] = "";
        if (friction_magnification_ != 1) std::snprintf(magnified, sizeof magnified, " \u00d7%g", friction_magnification_);
        const Point tip = from + Point(friction_magnification_ * scale_.length(law_.friction(u, v)), 0);
        out.push_back({kind, {from, tip}, colors_.drag,
                       std::string("<i>f</i>") + magnified + kFrictionPhase[int(phase(row))]});
        break;
      }
      case ForceKind::weight:  // down from the centre, where the spring's force starts too
        out.push_back({kind, {c, c - Point(0, kVertical * l.body_height)}, colors_.wire_force, "<i>mg</i>"});
        break;
      case ForceKind::normal:  // as long as mg: equal and opposite
        out.push_back({kind, {foot, foot + Point(0, kVertical * l.body_height)}, colors_.wire_force, "<i>N</i>"});
        break;
      default: break;
    }
  return out;
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
  const double u = row[1];
  const render::Stroke ink{colors_.wire, 2.2};
  const double left = l.body_left(u);
  render::SpringShape spring;
  spring.width = 0.28 * l.unit, spring.lead = 0.18 * l.unit, spring.coils = 9;
  render::draw_spring(canvas, view, Point(0, l.height_at(0.5)), Point(left, l.height_at(0.5)), spring, ink);
  render::draw_box(canvas, view, Point(left, 0), Point(left + l.body_width, l.body_height),
                   colors_.bob.with_alpha(0.85), {colors_.wire, 1.8});
  if (ghost()) return;
  const auto [rest, body] = l.u_dimension(u);
  render::draw_dimension(canvas, view, rest, body, "<i>u</i>", Point(0, -1), colors_.wire, colors_.background);

  for (const DrawnForce& f : forces(row)) {
    render::ForceArrow arrow{f.arrow.from, f.arrow.to, f.color, f.label};
    if (f.kind != ForceKind::spring) arrow.place = render::LabelPlace::beside, arrow.side = label_side(f.kind);
    render::draw_force_arrow(canvas, view, arrow, colors_.background);
  }
}

std::optional<ForceKey> SlidingBoxDiagram::force_key() const {
  // mg and N are drawn at a fixed length: the key says so.
  std::string note = "<i>mg</i>, <i>N</i> not to scale";
  if (friction_magnification_ != 1 && seen_.has(ForceKind::friction)) {
    char magnified[64];
    std::snprintf(magnified, sizeof magnified, "<i>f</i> drawn \u00d7%g, ", friction_magnification_);
    note = magnified + note;
  }
  const std::vector<KeyEntry> table = {{ForceKind::spring, {colors_.gravity, "−<i>s</i>(<i>u</i>) spring"}},
                                       {ForceKind::friction, {colors_.drag, "<i>f</i> friction"}},
                                       {ForceKind::weight, {colors_.wire_force, "<i>mg</i>, <i>N</i> weight, floor"}}};
  return ForceKey{scale_.per_force(), "", note, seen_.names(table)};
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
