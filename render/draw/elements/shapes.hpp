// Basic shapes in world units: strokes, arrows, arcs, circles, polylines, hatched ceilings and the pendulum's pivot.
#pragma once
#include <algorithm>
#include <optional>
#include <utility>
#include <span>

#include "render/draw/canvas.hpp"

namespace vibra::render {

/// How a line is stroked. Widths are in 720p pixels (scaled by Canvas::scale()).
struct Stroke {
  Color color = palette::ink;
  double width = 2;
  bool dashed = false;
  /// Where in the dash pattern the path starts (pixels): a piece of a longer
  /// path keeps the phase the whole path has there.
  double dash_offset = 0;
};

// Shapes in world units through a WorldView. No physics here.
void draw_line(Canvas&, const WorldView&, const Point& a, const Point& b, const Stroke&);
/// An arrow from `from` to `to` with a filled head of `head` 720p pixels
/// (shrunk for short arrows so the head never overshoots the tip).
/// A band of another colour under a mark, `reach` 720p pixels wide on each
/// side: the mark then sits on it, whatever it crosses (a force on a body).
struct Casing {
  Color color;
  double reach = 2.5;
  /// Square at the tail, reaching no further back than the shaft: for an
  /// arrow that starts at a body's rim, whose outline it must not bite.
  bool square_tail = false;
  /// In device pixels: never under 3, so past the mark's 1-pixel fringe
  /// of antialiasing a whole pixel of casing remains at any size.
  double device_reach(double scale) const { return std::max(reach * scale, 3.0); }
};
void draw_arrow(Canvas&, const WorldView&, const Point& from, const Point& to, const Stroke&, double head = 20,
                const std::optional<Casing>& = std::nullopt);
/// The same in pixels.
void draw_pixel_arrow(Canvas&, const Point& from, const Point& to, const Stroke&, double head = 20,
                      const std::optional<Casing>& = std::nullopt);
void draw_circle(Canvas&, const WorldView&, const Point& center, double radius, const Color& fill, const Stroke& outline);
/// An arc from angle a0 to a1 (radians, counter-clockwise from +x in the world).
void draw_arc(Canvas&, const WorldView&, const Point& center, double radius, double a0, double a1, const Stroke&);
/// A ceiling: a thick line of half-width `half_width` centred at `center`
/// with hatching above it, and a small pin at the centre.
void draw_ceiling(Canvas&, const WorldView&, const Point& center, double half_width, const Stroke&);
/// A pivot that nothing hangs from: a square bearing block, `half_width`
/// (world units) each side of `center`, with the axle pin drawn on it. For a
/// pendulum that swings up past its pivot, which a ceiling would cut.
void draw_pivot_block(Canvas&, const WorldView&, const Point& center, double half_width, const Color& fill,
                      const Stroke&);

/// The unit vector along a -> b and the one 90 degrees counter-clockwise
/// from it; along = +x for a == b. The length is taken with hypot: a
/// drawing scaled to a run of 1e200 has segments whose squared length
/// overflows, and its springs and dashpots came out as nothing.
std::pair<Point, Point> segment_axes(const Point& a, const Point& b);

// Shapes in pixels, for plots.
void draw_pixel_polyline(Canvas&, std::span<const Point> points, const Stroke&);
void draw_pixel_line(Canvas&, const Point& a, const Point& b, const Stroke&);
/// Separate segments a-b in one stroke: one pass of Cairo (and of its clip) for hatching.
void draw_pixel_segments(Canvas&, std::span<const std::pair<Point, Point>> segments, const Stroke&);
void fill_pixel_rect(Canvas&, const PixelRect&, const Color&);
/// A filled disc of `radius` pixels (a mesh point's mark on a curve).
void fill_pixel_disc(Canvas&, const Point& center, double radius, const Color&);

}  // namespace vibra::render
