// A software stroke for plain strokes on image surfaces, pixel-equal to Cairo's own but faster.
#pragma once
#include <cairo.h>

#include <cstdint>

namespace vibra::render {

/// Strokes the current path of `cr` in software, and clears the path, when
/// the stroke is a plain one on pixels: a solid source drawn OVER an image
/// surface (the canvas or a group on it), a transform that only shifts, a
/// whole-pixel rectangular clip, and round joins (or joins that turn so
/// little that their style makes no visible difference). Returns false,
/// leaving everything as it was, for any other stroke: Cairo draws it.
///
/// Why: Cairo 1.16's antialiased rasterizer costs about 70 ns for each pixel
/// a line covers and 1.7 us for each vertex of a polyline, and strokes were
/// half of a comparison frame's drawing. Here each pixel's coverage is its
/// distance to the nearest segment (a one-pixel ramp across the edge, exact
/// for lines along the axes), the segments of one stroke are joined by taking
/// the largest coverage (so joins are round and no pixel is painted twice),
/// and the coverage is blended as Cairo blends a mask: 8-bit, premultiplied.
/// Line ends follow the cap: round, butt (cut square at the end point) or
/// square (cut half a width beyond it). Dashes are Cairo's: the pattern
/// starts afresh at each subpath, and a closed outline's last dash runs on
/// into its first. A pixel's coverage depends only on the segments near it,
/// never on the clip, so a curve stroked strip by strip is the whole curve.
/// `scalar`: every pixel one at a time, as on a processor without AVX2 (the
/// vector loops' check: the same bytes).
bool raster_stroke(cairo_t* cr, bool scalar = false);

/// The length of a path's segment from (ax, ay) to (bx, by) as a stroke
/// measures it for its dashes: between the points as Cairo keeps them, at
/// whole 256ths of a pixel. A part of a dashed path, stroked with the dash
/// offset summed from these, has its dashes where the whole path has them.
double stroked_distance(double ax, double ay, double bx, double by);

/// The stroke's last step on one row: pixels[first .. last] = source IN
/// masks OVER pixels (premultiplied ARGB32, each channel times a / 255
/// rounded as pixman rounds), then masks[first .. last] = 0. `masks` has 7
/// bytes of room past `last` (read, written back unchanged). Eight pixels at
/// a time where the processor has AVX2, the same bytes as one at a time
/// (`one_at_a_time`).
void blend_span(std::uint32_t* pixels, std::uint8_t* masks, int first, int last, std::uint32_t source,
                bool one_at_a_time = false);

}  // namespace vibra::render
