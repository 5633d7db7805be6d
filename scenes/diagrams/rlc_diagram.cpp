// The series RLC circuit's diagram (section 1.12.11): source, resistor, inductor, capacitor, current and charge.
#include "scenes/diagrams/rlc_diagram.hpp"

#include <cmath>

#include "render/draw/annotations.hpp"
#include "render/draw/text.hpp"
#include "scenes/diagrams/diagram_registry.hpp"

namespace vibra::scenes {

namespace {
// The loop, world units: corners (0, 0) and (kWidth, kHeight).
constexpr double kWidth = 4, kHeight = 2.6;
const Point kSourceFrom(0, 0.7), kSourceTo(0, 1.9);          // + at the top
const Point kResistorFrom(1.2, kHeight), kResistorTo(2.8, kHeight);
const Point kInductorFrom(kWidth, 1.95), kInductorTo(kWidth, 0.65);
const Point kCapacitorFrom(1.6, 0), kCapacitorTo(2.4, 0);    // + on the right plate for q > 0
constexpr double kGap = 0.3, kPlate = 0.8, kCurrentOffset = -0.4;
}  // namespace

RlcDiagram::RlcDiagram(SceneColors colors) : colors_(colors) {}

std::vector<PanelSpec> RlcDiagram::panels() const {
  auto column = [](int i) { return [i](std::span<const double> row) { return row[i]; }; };
  return {{"<i>I</i>  current", {{"", colors_.bob, column(2)}}},
          {"<i>q</i>  charge", {{"", colors_.gravity, column(1)}}},
          {"<i>V</i>  source", {{"", colors_.wire_force, column(3)}}}};
}

void RlcDiagram::record(std::span<const double> row, WorldBox&) {
  if (std::isfinite(row[1])) largest_q_ = std::max(largest_q_, std::abs(row[1]));
  if (std::isfinite(row[2])) largest_I_ = std::max(largest_I_, std::abs(row[2]));
}

void RlcDiagram::finish_recording(WorldBox& world) {
  // The loop, its parts' labels around it, the capacitor's signs below.
  world.extend(Point(-0.95, -0.75));
  world.extend(Point(kWidth + 0.85, kHeight + 0.45));
}

render::CurrentArrow RlcDiagram::current_arrow(std::span<const double> row) const {
  const double length = largest_I_ > 0 ? kLongestCurrent * row[2] / largest_I_ : 0;
  return render::current_arrow(kResistorFrom, kResistorTo, kCurrentOffset, length);
}

render::CapacitorGeometry RlcDiagram::capacitor(std::span<const double> row) const {
  return render::capacitor_geometry(kCapacitorFrom, kCapacitorTo, kGap, kPlate, charge_share(row));
}

void RlcDiagram::draw_static(render::Canvas& canvas, const render::WorldView& view) const {
  const render::Stroke ink{colors_.wire, 2.2};
  const Point wire[] = {kCapacitorFrom, Point(0, 0), kSourceFrom};
  render::draw_wire(canvas, view, wire, ink);
  const Point top[] = {kSourceTo, Point(0, kHeight), kResistorFrom};
  render::draw_wire(canvas, view, top, ink);
  const Point right[] = {kResistorTo, Point(kWidth, kHeight), kInductorFrom};
  render::draw_wire(canvas, view, right, ink);
  const Point bottom[] = {kInductorTo, Point(kWidth, 0), kCapacitorTo};
  render::draw_wire(canvas, view, bottom, ink);
  render::draw_voltage_source(canvas, view, kSourceFrom, kSourceTo, 0.38, ink, colors_.background);
  render::draw_resistor(canvas, view, kResistorFrom, kResistorTo, 0.34, ink);
  render::draw_inductor(canvas, view, kInductorFrom, kInductorTo, 4, ink);

  render::TextStyle label{24, colors_.wire};
  auto at = [&](const Point& p) { return view.to_pixel(p); };
  render::draw_text(canvas, at(Point(-0.5, 0.5 * (kSourceFrom.y() + kSourceTo.y()))), "<i>V</i>(<i>t</i>)", label,
                    render::Anchor::right);
  render::draw_text(canvas, at(0.5 * (kResistorFrom + kResistorTo) + Point(0, 0.28)), "<i>R</i>", label,
                    render::Anchor::bottom);
  render::draw_text(canvas, at(0.5 * (kInductorFrom + kInductorTo) + Point(0.42, 0)), "<i>L</i>", label,
                    render::Anchor::left);
  render::draw_text(canvas, at(0.5 * (kCapacitorFrom + kCapacitorTo) + Point(0, -0.5 * kPlate - 0.1)), "<i>C</i>",
                    label, render::Anchor::top);
}

void RlcDiagram::draw(render::Canvas& canvas, const render::WorldView& view, std::span<const double> row) {
  const render::CurrentArrow arrow = current_arrow(row);
  if (ghost()) {  // the current alone: one circuit's plates hold one charge
    render::draw_force_arrow(canvas, view, {arrow.from, arrow.to, colors_.bob, ""}, colors_.background);
    return;
  }
  render::draw_capacitor(canvas, view, kCapacitorFrom, kCapacitorTo, kGap, kPlate, charge_share(row), {colors_.wire, 2.2},
                         colors_.gravity, colors_.bob);
  render::draw_force_arrow(canvas, view, {arrow.from, arrow.to, colors_.bob, "<i>I</i>", render::LabelPlace::beside,
                                          Point(0, 1)}, colors_.background);
}

DiagramKind rlc_diagram_kind() {
  return {"rlc",
          "series RLC circuit: source, resistor, inductor and capacitor; an arrow for I, signs on the plates for q "
          "(section 1.12.11)",
          {"rlc"}, [](const DiagramInput& in) { return std::make_unique<RlcDiagram>(in.config.colors); }};
}

}  // namespace vibra::scenes
