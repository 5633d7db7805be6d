// Outline: the shape of a recorded piece of a drawing and what it is, for the placer and for checks.
#pragma once
#include <cairo.h>

#include <string>
#include <utility>
#include <vector>

#include "render/draw/canvas.hpp"

namespace vibra::render {

/// What a recorded piece of a drawing is, so that a check can say what a
/// label covers ("the spring"), and the placer can treat all alike.
enum class OutlineKind { drawing, body, spring, wire, arrow, ground, label, legend, text, formula };
const char* outline_kind_name(OutlineKind);

/// One stroke or fill of a drawing in pixels: the segments of its flattened
/// path with the half width of its line (0 for a fill), and, for a fill, its
/// closed polygons.
struct OutlineShape {
  OutlineKind kind = OutlineKind::drawing;
  std::vector<std::pair<Point, Point>> segments;
  double half_width = 0;
  std::vector<std::vector<Point>> polygons;
  PixelRect bounds;  ///< covers the segments widened by half_width, and the polygons
  std::string name;  ///< a label's text, for messages
};

/// What a drawing covers, shape by shape, as the kit drew it: recorded by a
/// Canvas between record_into(&outline) and record_into(nullptr) from every
/// stroke and fill (their flattened paths, in device pixels) and every text
/// box. The label placer keeps labels off it; tests check a frame against it.
class Outline {
 public:
  /// The current path of `cr` as stroked with its line width, or filled.
  void add_stroke(cairo_t* cr, OutlineKind);
  void add_fill(cairo_t* cr, OutlineKind);
  void add_box(const PixelRect&, OutlineKind, std::string name = {});
  /// A filled polygon in pixels (closed for you), for what is painted other
  /// than by strokes and fills (a road pasted from tiles).
  void add_polygon(std::vector<Point> polygon, OutlineKind);
  void append(const Outline& other);
  void clear() { shapes_.clear(); }
  const std::vector<OutlineShape>& shapes() const { return shapes_; }

 private:
  std::vector<OutlineShape> shapes_;
};

/// Whether `rect` touches the shape (its stroked segments or filled polygons).
bool overlaps(const PixelRect& rect, const OutlineShape&);
/// The smallest distance from `p` to the segment a-b.
double distance_to_segment(const Point& p, const Point& a, const Point& b);

}  // namespace vibra::render
