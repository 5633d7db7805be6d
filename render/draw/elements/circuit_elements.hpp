// The parts of a circuit schematic, in world units, each drawn between two terminals `from` and `to` on the loop's wire.
// No physics here: the caller says how large the current arrow and the charge
// marks are.
#pragma once
#include <span>
#include <string>

#include "render/draw/elements/shapes.hpp"

namespace vibra::render {

/// Straight wires through `points`.
void draw_wire(Canvas&, const WorldView&, std::span<const Point> points, const Stroke&);
/// A resistor: the zigzag of IEC 60617's older (US) symbol, `width` across.
void draw_resistor(Canvas&, const WorldView&, const Point& from, const Point& to, double width, const Stroke&);
/// An inductor: `loops` half circles side by side along the wire.
void draw_inductor(Canvas&, const WorldView&, const Point& from, const Point& to, int loops, const Stroke&);
/// A voltage source: a circle of `radius` on the wire with + toward `to`
/// and - toward `from`, and the wire broken inside it.
void draw_voltage_source(Canvas&, const WorldView&, const Point& from, const Point& to, double radius, const Stroke&,
                         const Color& background);

/// A capacitor between `from` and `to`: two plates across the wire, `gap`
/// apart and `plate` long. The plate nearer `to` holds +`charge`, the other
/// -`charge`; `charge` in [-1, 1] (a fraction of the largest) sets how many
/// + and - marks sit beside each plate (up to 5) and how strongly the plates
/// are tinted.
struct CapacitorGeometry {
  Point plate_from[2], plate_to[2];  ///< [0] the plate nearer `from`, [1] nearer `to`
  int marks = 0;                     ///< number of signs beside each plate
  double sign_of_to_plate = 0;       ///< +1: the plate nearer `to` is positive
};
CapacitorGeometry capacitor_geometry(const Point& from, const Point& to, double gap, double plate, double charge);
void draw_capacitor(Canvas&, const WorldView&, const Point& from, const Point& to, double gap, double plate,
                    double charge, const Stroke&, const Color& positive, const Color& negative);

/// An arrow for a current beside the wire from `a` to `b`: centred on the
/// segment's middle, `offset` to its left (world units), `length` long in
/// the direction of `a` to `b` (negative: from `b` toward `a`), labelled.
struct CurrentArrow {
  Point from, to;
};
CurrentArrow current_arrow(const Point& a, const Point& b, double offset, double length);

}  // namespace vibra::render
