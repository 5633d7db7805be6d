// The spring-mass system's diagram (Figs 1.17, 1.18): wall, spring, body on wheels, dashpot and forces.
#include "scenes/diagrams/oscillator_diagram.hpp"

#include <cmath>

#include "render/draw/annotations.hpp"
#include "render/draw/elements/machine_elements.hpp"
#include "scenes/diagrams/diagram_registry.hpp"
#include "scenes/panels/plot_panels.hpp"

namespace vibra::scenes {

namespace {
constexpr const char* kSpringLabel[] = {"−<i>ku</i>", "−<i>s</i>(<i>u</i>)"};
std::string damper_label(Damping d) { return d == Damping::quadratic ? "−<i>b</i>|<i>u</i>′|<i>u</i>′" : "−<i>bu</i>′"; }
}  // namespace

OscillatorDiagram::OscillatorDiagram(VibrationLaw law, std::function<double(double)> exact, SceneColors colors)
    : law_(std::move(law)), exact_(std::move(exact)), colors_(colors) {}

std::vector<PanelSpec> OscillatorDiagram::panels() const {
  std::vector<PanelSpec> out;
  PanelSpec u{"<i>u</i>  displacement", {{"numerical", colors_.bob, [](std::span<const double> r) { return r[1]; }}}};
  if (exact_) u.series.push_back({"exact", colors_.gravity, [e = exact_](std::span<const double> r) { return e(r[0]); }, true});
  out.push_back(std::move(u));
  out.push_back({quantity_markup("v"), {{"", colors_.bob, [](std::span<const double> r) { return r[2]; }}}});
  if (has_damper() || law_.F) {
    PanelSpec forces{"forces on the body", {}};
    forces.series.push_back({std::string("spring ") + kSpringLabel[law_.s ? 1 : 0], colors_.gravity,
                             [law = law_](std::span<const double> r) { return -law.spring(r[1]); }});
    if (has_damper())
      forces.series.push_back({"damper " + damper_label(law_.damping), colors_.drag,
                               [law = law_](std::span<const double> r) { return -law.damper(r[2]); }});
    if (law_.F)
      forces.series.push_back({"<i>F</i>(<i>t</i>)", colors_.wire_force,
                               [law = law_](std::span<const double> r) { return law.external(r[0]); }});
    out.push_back(std::move(forces));
  }
  return out;
}

void OscillatorDiagram::record(std::span<const double> row, WorldBox&) {
  largest_u_ = std::max(largest_u_, std::abs(row[1]));
  lowest_u_ = std::min(lowest_u_, row[1]), highest_u_ = std::max(highest_u_, row[1]);
  const double forces[] = {-law_.spring(row[1]), -law_.damper(row[2]), law_.external(row[0])};
  for (int i = 0; i < 3; ++i) {
    scale_.see(forces[i]);
    if (std::isfinite(forces[i])) pushes_right_[i] = std::max(pushes_right_[i], forces[i]);
  }
}

void OscillatorDiagram::finish_recording(WorldBox& world) {
  layout_.emplace(largest_u_, true);
  scale_.set_longest(1.1 * layout_->unit);
  world.extend(layout_->extent());
  // Arrows start on the body's centre line, at equilibrium_x + u; the view
  // reaches as far right as their tips and labels can, and no farther, so the
  // drawing stays centred. A linear spring's tip is exact: at
  // equilibrium_x + u (1 - per k), linear in u. The other forces are bounded
  // by the body's farthest right plus their largest push.
  const double per = scale_.per_force(), body = layout_->equilibrium_x() + highest_u_;
  double reach = body;
  if (law_.linear_spring()) {
    const double shrink = 1 - per * law_.k;
    reach = std::max(reach, layout_->equilibrium_x() + std::max(lowest_u_ * shrink, highest_u_ * shrink));
  }
  for (int i = law_.linear_spring() ? 1 : 0; i < 3; ++i) reach = std::max(reach, body + per * pushes_right_[i]);
  world.extend(Point(reach + 0.5 * layout_->unit, layout_->body_bottom()));
}

double OscillatorDiagram::wheel_turn(double u) const { return -u / layout_->wheel_radius; }

double OscillatorDiagram::spring_height() const { return layout_->height_at(has_damper() ? 0.75 : 0.5); }

std::vector<Arrow> OscillatorDiagram::force_arrows(std::span<const double> row) const {
  const double t = row[0], u = row[1], v = row[2];
  const double x = layout_->body_center(u).x();
  std::vector<Arrow> arrows;
  const double ys = has_damper() || law_.F ? layout_->height_at(0.72) : layout_->height_at(0.5);
  arrows.push_back({{x, ys}, {x + scale_.length(-law_.spring(u)), ys}});
  if (has_damper()) arrows.push_back({{x, layout_->height_at(0.28)}, {x + scale_.length(-law_.damper(v)), layout_->height_at(0.28)}});
  if (law_.F) arrows.push_back({{x, layout_->height_at(0.5)}, {x + scale_.length(law_.external(t)), layout_->height_at(0.5)}});
  return arrows;
}

void OscillatorDiagram::draw_static(render::Canvas& canvas, const render::WorldView& view) const {
  const HorizontalLayout& l = *layout_;
  const render::Stroke ink{colors_.wire, 2.2};
  render::draw_hatched_surface(canvas, view, Point(0, 0), Point(0, l.wall_height), Point(-1, 0), ink);
  render::draw_hatched_surface(canvas, view, Point(-0.3 * l.unit, 0), Point(l.extent().max().x(), 0), Point(0, -1), ink);
  // The equilibrium: a dashed vertical through the body's centre at rest.
  const double top = l.body_bottom() + l.body_height + 0.55 * l.unit;
  render::draw_line(canvas, view, Point(l.equilibrium_x(), 0), Point(l.equilibrium_x(), top),
                    {colors_.wire.with_alpha(0.5), 1.4, true});
}

void OscillatorDiagram::draw(render::Canvas& canvas, const render::WorldView& view, std::span<const double> row) {
  const HorizontalLayout& l = *layout_;
  const double u = row[1];
  const render::Stroke ink{colors_.wire, 2.2};
  const double left = l.body_left(u);
  render::SpringShape spring;
  spring.width = 0.28 * l.unit, spring.lead = 0.18 * l.unit, spring.coils = 9;
  render::draw_spring(canvas, view, Point(0, spring_height()), Point(left, spring_height()), spring, ink);
  if (has_damper()) {
    render::DashpotShape dashpot;
    dashpot.width = 0.26 * l.unit, dashpot.rest_length = l.rest_length, dashpot.cylinder = 0.38;
    render::draw_dashpot(canvas, view, Point(0, damper_height()), Point(left, damper_height()), dashpot, ink);
  }
  for (double f : {0.25, 0.75})
    render::draw_wheel(canvas, view, Point(left + f * l.body_width, l.wheel_radius), l.wheel_radius,
                       wheel_turn(u), colors_.background, {colors_.wire, 1.8});
  render::draw_box(canvas, view, Point(left, l.body_bottom()), Point(left + l.body_width, l.body_bottom() + l.body_height),
                   colors_.bob.with_alpha(0.85), {colors_.wire, 1.8});
  if (ghost()) return;

  const auto [rest, body] = l.u_dimension(u);
  render::draw_dimension(canvas, view, rest, body, "<i>u</i>", Point(0, -1), colors_.wire, colors_.background);

  const std::vector<Arrow> arrows = force_arrows(row);
  const render::Color colors[] = {colors_.gravity, has_damper() ? colors_.drag : colors_.wire_force, colors_.wire_force};
  // The spring runs from the wall to the body: u < 0 compresses it.
  const std::string labels[] = {kSpringLabel[law_.s ? 1 : 0] + std::string(spring_state(u)), has_damper() ? damper_label(law_.damping) : "<i>F</i>(<i>t</i>)",
                                "<i>F</i>(<i>t</i>)"};
  for (size_t i = 0; i < arrows.size(); ++i)
    render::draw_force_arrow(canvas, view, {arrows[i].from, arrows[i].to, colors[i], labels[i]}, colors_.background);
}

std::optional<ForceKey> OscillatorDiagram::force_key() const {
  std::vector<ForceName> names = {{colors_.gravity, std::string(kSpringLabel[law_.s ? 1 : 0]) + " spring"}};
  if (has_damper()) names.push_back({colors_.drag, damper_label(law_.damping) + " damping"});
  if (law_.F) names.push_back({colors_.wire_force, "<i>F</i>(<i>t</i>) driving force"});
  // On wheels on a level floor: the weight and the floor's push cancel, and only horizontal forces move it.
  return ForceKey{scale_.per_force(), "", "<i>mg</i>, <i>N</i> cancel: not drawn", names};
}

DiagramKind oscillator_diagram_kind() {
  return {"oscillator",
          "spring-mass on wheels (Figs 1.17, 1.18): wall, spring, dashpot when b > 0, u marked, arrows -s(u), -f(u'), F(t)",
          {"vibration"}, [](const DiagramInput& in) {
            return std::make_unique<OscillatorDiagram>(VibrationLaw::from(in.parameters), in.info.exact, in.config.colors);
          }};
}

}  // namespace vibra::scenes
