// The boxes a typeset formula is made of: glyphs, rules and strokes with their extents.
#pragma once
#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "render/draw/canvas.hpp"
#include "render/typeset/math_symbols.hpp"

typedef struct _PangoLayout PangoLayout;

namespace vibra::render {

/// A rectangle by its edges, in pixels, y down; empty until something is added.
struct InkBox {
  double x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY;
  bool empty() const { return !(x1 >= x0 && y1 >= y0); }
  void add(const InkBox& o) {
    if (o.empty()) return;
    x0 = std::min(x0, o.x0), y0 = std::min(y0, o.y0), x1 = std::max(x1, o.x1), y1 = std::max(y1, o.y1);
  }
  InkBox moved(const Point& by) const {
    return empty() ? *this : InkBox{x0 + by.x(), y0 + by.y(), x1 + by.x(), y1 + by.y()};
  }
  InkBox widened(double d) const { return empty() ? *this : InkBox{x0 - d, y0 - d, x1 + d, y1 + d}; }
  PixelRect rect() const { return empty() ? PixelRect{} : PixelRect{x0, y0, x1 - x0, y1 - y0}; }
};

/// A typeset formula or rich text as a tree of boxes, TeX's way: each box has
/// its origin on its baseline at its left end, a width, a height above the
/// baseline (ascent) and a depth below it (descent), and its children at
/// offsets from that origin (pixels, y down). The leaves are what is drawn:
/// glyph runs set by Pango, rules (a fraction's bar, \bar) and strokes
/// (delimiters sized to their content, a radical's sign).
struct MathBox {
  enum class Role {
    row,          ///< children side by side
    line,         ///< one line of a formula or of wrapped rich text
    glyphs,       ///< a run of glyphs (leaf)
    rule,         ///< a filled rectangle: its own box (leaf)
    stroke,       ///< a polyline of `line_width` (leaf)
    fraction,     ///< children: numerator, bar (a rule), denominator
    numerator,
    denominator,
    scripts,      ///< children: the base, then the superscript and/or the subscript
    base,
    superscript,
    subscript,
    radical,      ///< children: the sign (a stroke), the radicand
    delimited,    ///< children: the opening delimiter, the content, the closing one
    delimiter,
    accent,       ///< children: the base, the accent
    space,
  };
  Role role = Role::row;
  Point at = Point(0, 0);  ///< origin relative to the parent's origin
  double width = 0, ascent = 0, descent = 0;
  InkBox ink;              ///< where the box draws, relative to its own origin
  Atom atom = Atom::ord;
  double italic_correction = 0;  ///< how far an italic glyph leans beyond its width

  // Leaves.
  std::string text;                     ///< glyphs: UTF-8
  MathFont font = MathFont::upright;    ///< glyphs
  double size = 0;                      ///< glyphs: pixels per em
  Point layout_offset = Point(0, 0);    ///< glyphs: the Pango layout's top-left from the origin
  std::shared_ptr<PangoLayout> layout;  ///< glyphs
  std::vector<Point> points;            ///< stroke
  double line_width = 0;                ///< stroke

  std::vector<MathBox> children;

  double height() const { return ascent + descent; }
  /// The box in pixels when its origin is at `origin`.
  PixelRect rect_at(const Point& origin) const { return {origin.x(), origin.y() - ascent, width, ascent + descent}; }
};

/// Calls `leaf(box, origin)` for every leaf of the tree, with its origin in the
/// coordinates `origin` is given in.
template <class Leaf>
void for_each_leaf(const MathBox& box, const Point& origin, Leaf&& leaf) {
  if (box.children.empty()) {
    if (box.role == MathBox::Role::glyphs || box.role == MathBox::Role::rule || box.role == MathBox::Role::stroke)
      leaf(box, origin);
    return;
  }
  for (const MathBox& child : box.children) for_each_leaf(child, origin + child.at, leaf);
}

}  // namespace vibra::render
