// Draws a typeset formula's boxes on a canvas, with a halo in the background colour.
#include "render/typeset/formula_draw.hpp"

#include <pango/pangocairo.h>

#include "render/labels/drawing_record.hpp"

namespace vibra::render {

namespace {
using Role = MathBox::Role;

/// The leaf's outline as a Cairo path at `origin`: glyph outlines, the rule's
/// rectangle, or the stroke's polyline.
void leaf_path(cairo_t* cr, const MathBox& leaf, const Point& origin) {
  if (leaf.role == Role::glyphs) {
    pango_cairo_update_layout(cr, leaf.layout.get());
    cairo_move_to(cr, origin.x() + leaf.layout_offset.x(), origin.y() + leaf.layout_offset.y());
    pango_cairo_layout_path(cr, leaf.layout.get());
  } else if (leaf.role == Role::rule) {
    cairo_rectangle(cr, origin.x(), origin.y() - leaf.ascent, leaf.width, leaf.ascent);
  } else {
    for (size_t i = 0; i < leaf.points.size(); ++i) {
      const Point p = origin + leaf.points[i];
      if (i == 0) cairo_move_to(cr, p.x(), p.y());
      else cairo_line_to(cr, p.x(), p.y());
    }
  }
}

void paint_leaf(cairo_t* cr, const MathBox& leaf, const Point& origin) {
  if (leaf.role == Role::glyphs) {
    pango_cairo_update_layout(cr, leaf.layout.get());
    cairo_move_to(cr, origin.x() + leaf.layout_offset.x(), origin.y() + leaf.layout_offset.y());
    pango_cairo_show_layout(cr, leaf.layout.get());
    cairo_new_path(cr);
    return;
  }
  leaf_path(cr, leaf, origin);
  if (leaf.role == Role::rule) {
    cairo_fill(cr);
  } else {
    cairo_set_line_width(cr, leaf.line_width);
    cairo_stroke(cr);
  }
}
}  // namespace

double math_halo_reach(const MathPaint& paint, double scale) { return paint.halo ? 2.5 * scale : 0; }

PixelRect draw_math(Canvas& canvas, const MathBox& box, const Point& origin, const MathPaint& paint,
                    const std::string& name) {
  cairo_t* cr = canvas.cr();
  const double reach = math_halo_reach(paint, canvas.scale());
  InkBox all;
  for_each_leaf(box, origin, [&](const MathBox& leaf, const Point& at) {
    // A pixel more than the ink: anti-aliasing reaches into the next pixel.
    const InkBox ink = leaf.ink.moved(at).widened(reach + 1);
    if (ink.empty()) return;
    all.add(ink);
    canvas.mark_drawn(ink.x0, ink.y0, ink.x1, ink.y1);
    if (DrawingRecord* record = canvas.record()) record->outline.add_box(ink.rect(), OutlineKind::formula, name);
  });
  cairo_save(cr);
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  if (paint.halo) {
    cairo_set_source_rgba(cr, paint.halo_color.r, paint.halo_color.g, paint.halo_color.b, paint.halo_color.a);
    for_each_leaf(box, origin, [&](const MathBox& leaf, const Point& at) {
      cairo_new_path(cr);
      leaf_path(cr, leaf, at);
      cairo_set_line_width(cr, 2 * reach + (leaf.role == Role::stroke ? leaf.line_width : 0));
      if (leaf.role != Role::stroke) cairo_fill_preserve(cr);
      cairo_stroke(cr);
    });
  }
  cairo_set_source_rgba(cr, paint.color.r, paint.color.g, paint.color.b, paint.color.a);
  for_each_leaf(box, origin, [&](const MathBox& leaf, const Point& at) { paint_leaf(cr, leaf, at); });
  cairo_restore(cr);
  return all.rect();
}

PixelRect draw_formula(Canvas& canvas, const std::string& source, const Point& origin, const MathStyle& style,
                       const MathPaint& paint) {
  const MathBox box = layout_formula(canvas, parse_formula(source), style);
  return draw_math(canvas, box, origin, paint, source);
}

}  // namespace vibra::render
