// The parts of a circuit schematic, in world units, each drawn between two terminals `from` and `to` on the loop's wire.
#include "render/draw/elements/circuit_elements.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "render/draw/elements/machine_elements.hpp"
#include "render/labels/drawing_record.hpp"

namespace vibra::render {

void draw_wire(Canvas& canvas, const WorldView& view, std::span<const Point> points, const Stroke& stroke) {
  OutlineKindScope outline_kind(canvas, OutlineKind::wire);
  for (size_t i = 1; i < points.size(); ++i) draw_line(canvas, view, points[i - 1], points[i], stroke);
}

void draw_resistor(Canvas& canvas, const WorldView& view, const Point& from, const Point& to, double width,
                   const Stroke& stroke) {
  // The resistor's zigzag is a spring's, with short leads and three zigs.
  SpringShape zigzag;
  zigzag.width = width, zigzag.lead = 0.12 * (to - from).norm(), zigzag.coils = 3;
  draw_spring(canvas, view, from, to, zigzag, stroke);
}

void draw_inductor(Canvas& canvas, const WorldView& view, const Point& from, const Point& to, int loops,
                   const Stroke& stroke) {
  const auto [along, across] = segment_axes(from, to);
  const double r = 0.5 * (to - from).norm() / std::max(1, loops);
  const double start = std::atan2(along.y(), along.x());
  // Each loop is a half circle on the right of the wire (clockwise from -along to +along).
  for (int i = 0; i < loops; ++i) {
    const Point center = from + (2 * i + 1) * r * along;
    draw_arc(canvas, view, center, r, start + M_PI, start, stroke);
  }
}

void draw_voltage_source(Canvas& canvas, const WorldView& view, const Point& from, const Point& to, double radius,
                         const Stroke& stroke, const Color& background) {
  const auto [along, across] = segment_axes(from, to);
  const Point center = 0.5 * (from + to);
  draw_line(canvas, view, from, center - radius * along, stroke);
  draw_line(canvas, view, center + radius * along, to, stroke);
  draw_circle(canvas, view, center, radius, background, stroke);
  // + and - inside the circle, + toward `to`.
  const double s = 0.28 * radius;
  const Point plus = center + 0.45 * radius * along, minus = center - 0.45 * radius * along;
  draw_line(canvas, view, plus - s * along, plus + s * along, stroke);
  draw_line(canvas, view, plus - s * across, plus + s * across, stroke);
  draw_line(canvas, view, minus - s * across, minus + s * across, stroke);
}

CapacitorGeometry capacitor_geometry(const Point& from, const Point& to, double gap, double plate, double charge) {
  const auto [along, across] = segment_axes(from, to);
  const Point center = 0.5 * (from + to);
  CapacitorGeometry g;
  for (int i = 0; i < 2; ++i) {
    const Point at = center + (i == 0 ? -0.5 : 0.5) * gap * along;
    g.plate_from[i] = at - 0.5 * plate * across;
    g.plate_to[i] = at + 0.5 * plate * across;
  }
  const double q = std::clamp(charge, -1.0, 1.0);
  g.marks = static_cast<int>(std::lround(5 * std::abs(q)));
  g.sign_of_to_plate = q > 0 ? 1 : q < 0 ? -1 : 0;
  return g;
}

void draw_capacitor(Canvas& canvas, const WorldView& view, const Point& from, const Point& to, double gap, double plate,
                    double charge, const Stroke& stroke, const Color& positive, const Color& negative) {
  const auto [along, across] = segment_axes(from, to);
  const CapacitorGeometry g = capacitor_geometry(from, to, gap, plate, charge);
  const Point center = 0.5 * (from + to);
  draw_line(canvas, view, from, center - 0.5 * gap * along, stroke);
  draw_line(canvas, view, center + 0.5 * gap * along, to, stroke);
  const double strength = std::min(1.0, std::abs(charge));
  for (int i = 0; i < 2; ++i) {
    // The plate nearer `to` holds +charge.
    const double sign = (i == 1 ? 1 : -1) * g.sign_of_to_plate;
    const Color tint = sign > 0 ? positive : sign < 0 ? negative : stroke.color;
    draw_line(canvas, view, g.plate_from[i], g.plate_to[i], {sign == 0 ? stroke.color : tint.with_alpha(0.4 + 0.6 * strength),
                                                             2.2 * stroke.width});
    // The signs sit outside the gap beside the plate, in pairs off the wire.
    const double mark = 0.05 * plate;
    const Stroke ink{tint, 1.3 * stroke.width};
    for (int k = 0; k < g.marks; ++k) {
      const double level = (k % 2 == 0 ? 1 : -1) * (0.12 + 0.15 * (k / 2)) * plate;
      const Point p = 0.5 * (g.plate_from[i] + g.plate_to[i]) + level * across + (i == 0 ? -1.0 : 1.0) * 0.6 * gap * along;
      draw_line(canvas, view, p - mark * along, p + mark * along, ink);
      if (sign > 0) draw_line(canvas, view, p - mark * across, p + mark * across, ink);
    }
  }
}

CurrentArrow current_arrow(const Point& a, const Point& b, double offset, double length) {
  const auto [along, across] = segment_axes(a, b);
  const Point middle = 0.5 * (a + b) + offset * across;
  return {middle - 0.5 * length * along, middle + 0.5 * length * along};
}

}  // namespace vibra::render
