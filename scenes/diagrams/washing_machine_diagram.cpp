// The washing machine's diagram (section 1.12.4): a body on springs and a damper, shaken by its drum.
#include "scenes/diagrams/washing_machine_diagram.hpp"

#include <cmath>
#include <cstdio>

#include "core/models/model.hpp"
#include "render/draw/annotations.hpp"
#include "render/draw/elements/machine_elements.hpp"
#include "scenes/diagrams/forces/broken_force.hpp"
#include "scenes/diagrams/diagram_registry.hpp"

namespace vibra::scenes {

WashingMachineDiagram::WashingMachineDiagram(double beta, double gamma, std::function<double(double)> exact,
                                             SceneColors colors)
    : beta_(beta), gamma_(gamma), exact_(std::move(exact)), colors_(colors) {}

std::vector<PanelSpec> WashingMachineDiagram::panels() const {
  PanelSpec u{"<i>u</i>  (static deflections)", {{"numerical", colors_.bob, [](std::span<const double> r) { return r[1]; }}}};
  if (exact_) u.series.push_back({"exact", colors_.gravity, [e = exact_](std::span<const double> r) { return e(r[0]); }, true});
  if (beta_ > 0 || gamma_ != 1) {
    const double A = steady_amplitude(beta_, gamma_);
    u.series.push_back({"±steady amplitude", colors_.wire.with_alpha(0.55), [A](std::span<const double>) { return A; }, true});
    u.series.push_back({"", colors_.wire.with_alpha(0.55), [A](std::span<const double>) { return -A; }, true});
  }
  PanelSpec force{"forcing sin(<i>γt</i>)", {{"", colors_.wire_force, [g = gamma_](std::span<const double> r) {
                                               return std::sin(g * r[0]);
                                             }}}};
  return {std::move(u), std::move(force)};
}

void WashingMachineDiagram::record(std::span<const double> row, WorldBox&) {
  largest_u_ = std::max(largest_u_, std::abs(row[1]));
  scale_.see(row[1]);
  scale_.see(beta_ * row[2]);
}

namespace {
/// The divisor that draws a motion of `largest` static deflections within
/// `room`: 1, 2 or 5 times a power of ten, so the key's note reads round.
double round_divisor(double largest, double room) {
  if (!(largest > room) || !std::isfinite(largest)) return 1;
  const double needed = largest / room, decade = std::pow(10.0, std::floor(std::log10(needed)));
  for (double step : {1.0, 2.0, 5.0, 10.0})
    if (step * decade >= needed) return step * decade;
  return 10 * decade;
}
}  // namespace

void WashingMachineDiagram::finish_recording(WorldBox& world) {
  // The view is set by the machine: its motion is drawn divided by a round
  // number when larger than half its height (at resonance u grows to twenty
  // static deflections against a body three high).
  divisor_ = round_divisor(largest_u_, 0.5 * height_);
  const double drawn_u = largest_u_ / divisor_;
  // Legs long enough that the body never reaches the floor.
  leg_ = std::max(3.0, 1.35 * drawn_u + 0.8);
  // The drum's force, amplitude 1, reads at any scale; longer arrows are clipped.
  scale_.see(1);
  scale_.set_reference(1);
  scale_.set_longest(0.45 * height_ + 0.25 * std::min(drawn_u, 4.0));
  const double reach = scale_.longest();
  world.extend(Point(-0.5 * width_ - 1.0, -0.6));
  world.extend(Point(0.5 * width_ + 1.0, 0));
  world.extend(Point(0, body_bottom(largest_u_) + height_ + std::max(0.4, reach - 0.5 * height_ + 0.4)));
  world.extend(Point(0, body_bottom(-largest_u_) + 0.5 * height_ - reach - 0.4));
}

Point WashingMachineDiagram::drum_mass_offset(double t) const {
  const double phase = gamma_ * t;
  return 0.72 * drum_ * Point(std::cos(phase), std::sin(phase));
}

std::vector<Arrow> WashingMachineDiagram::force_arrows(std::span<const double> row) const {
  const double t = row[0], u = row[1], v = row[2];
  const Point c = body_center(u);
  std::vector<Arrow> arrows;
  arrows.push_back({c + Point(-1.45, 0), c + Point(-1.45, scale_.length(-u))});
  if (beta_ > 0) arrows.push_back({c + Point(1.45, 0), c + Point(1.45, scale_.length(-beta_ * v))});
  arrows.push_back({c, c + Point(0, scale_.length(std::sin(gamma_ * t)))});
  return arrows;
}

void WashingMachineDiagram::draw_static(render::Canvas& canvas, const render::WorldView& view) const {
  render::draw_hatched_surface(canvas, view, Point(-0.5 * width_ - 0.8, 0), Point(0.5 * width_ + 0.8, 0), Point(0, -1),
                               {colors_.wire, 2.2});
}

void WashingMachineDiagram::draw(render::Canvas& canvas, const render::WorldView& view, std::span<const double> row) {
  const double t = row[0], u = row[1];
  const render::Stroke ink{colors_.wire, 2.2};
  const double bottom = body_bottom(u);
  render::SpringShape spring;
  spring.width = 0.5, spring.lead = 0.3, spring.coils = 7;
  for (double x : {-1.3, 1.3}) render::draw_spring(canvas, view, Point(x, 0), Point(x, bottom), spring, ink);
  if (beta_ > 0) {
    render::DashpotShape dashpot;
    dashpot.width = 0.45, dashpot.rest_length = leg_, dashpot.cylinder = 0.4;
    render::draw_dashpot(canvas, view, Point(0, 0), Point(0, bottom), dashpot, ink);
  }
  render::draw_box(canvas, view, Point(-0.5 * width_, bottom), Point(0.5 * width_, bottom + height_),
                   colors_.bob.with_alpha(0.18), {colors_.wire, 2.2});
  // The drum, its spokes turning with the forcing's phase, and the off-centre mass.
  const Point c = body_center(u);
  render::draw_wheel(canvas, view, c, drum_, gamma_ * t, colors_.background, {colors_.wire, 1.8});
  render::draw_circle(canvas, view, c + drum_mass_offset(t), 0.2, colors_.bob, {colors_.wire, 1.4});
  if (ghost()) return;

  // Each label names its force ("spring −u", "drum sin(γt)"): two bare
  // formulas side by side, "−u sin(γt)", read as one product.
  const std::vector<Arrow> arrows = force_arrows(row);
  const double room = scale_.longest();
  draw_broken_force(canvas, view, room, {arrows[0].from, arrows[0].to, colors_.gravity, "spring −<i>u</i>"},
                    colors_.background);
  if (beta_ > 0)
    draw_broken_force(canvas, view, room, {arrows[1].from, arrows[1].to, colors_.drag, "damper −<i>βu</i>′"},
                      colors_.background);
  draw_broken_force(canvas, view, room, {arrows.back().from, arrows.back().to, colors_.wire_force, "drum sin(<i>γt</i>)"},
                    colors_.background);
}

std::optional<ForceKey> WashingMachineDiagram::force_key() const {
  std::vector<ForceName> names = {{colors_.gravity, "−<i>u</i> spring"}};
  if (beta_ > 0) names.push_back({colors_.drag, "−<i>βu</i>′ damping"});
  names.push_back({colors_.wire_force, "sin(<i>γt</i>) forcing"});
  char note[64] = "";
  if (divisor_ != 1) std::snprintf(note, sizeof note, "motion <i>u</i> drawn ÷%g", divisor_);
  return ForceKey{scale_.per_force(), "", note, names};
}

DiagramKind washing_machine_diagram_kind() {
  return {"washing_machine",
          "machine on springs and a damper, drum turning with an off-centre mass at the forcing's phase (section 1.12.4)",
          {"resonance"}, [](const DiagramInput& in) {
            return std::make_unique<WashingMachineDiagram>(in.parameters.number("beta"), in.parameters.number("gamma"),
                                                           in.info.exact, in.config.colors);
          }};
}

}  // namespace vibra::scenes
