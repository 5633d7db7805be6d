// Clips paths that reach far outside the picture before Cairo sees them (its 24.8 fixed point would wrap).
#pragma once
#include <cairo.h>

#include <span>

#include "render/draw/canvas.hpp"

namespace vibra::render {

/// Paths in pixels, clipped to a box far outside any picture before Cairo
/// sees them. Cairo keeps paths in 24.8 fixed point: a coordinate beyond
/// about 8 million pixels wraps around, so a body flown off to 1e200 (a
/// run that blows up, a force of 1e200) drew a stray line across the frame.
/// Clipped to ±kReach, every segment keeps its direction, so the part of it
/// in the picture is the part the exact path would draw; within the box the
/// calls are the plain ones, and ordinary frames are unchanged to the bit.
inline constexpr double kReach = 1 << 20;

/// Whether a point lies within the box (NaN does not).
bool within_reach(const Point&);
/// Adds the polyline to the current path: each segment clipped to the box,
/// a segment that leaves and comes back starting a new piece.
void add_polyline(cairo_t*, std::span<const Point> points);
/// Adds the polygon, clipped to the box (Sutherland-Hodgman), closed: a fill
/// keeps its shape inside the box.
void add_polygon(cairo_t*, std::span<const Point> points);
/// Adds the arc from a0 to a1 (radians, Cairo's direction: clockwise on the
/// screen when a1 > a0; negative: the other way) as its own sub-path;
/// nothing when it lies wholly outside the box, as a polygon clipped to it
/// when part of a huge circle reaches in.
void add_arc(cairo_t*, const Point& center, double radius, double a0, double a1, bool negative = false);

}  // namespace vibra::render
