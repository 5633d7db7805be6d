// Draws a typeset formula's boxes on a canvas, with a halo in the background colour.
#pragma once
#include <string>

#include "render/draw/canvas.hpp"
#include "render/draw/color.hpp"
#include "render/typeset/formula_layout.hpp"
#include "render/typeset/math_box.hpp"

namespace vibra::render {

/// The colours a typeset box is drawn in; a halo in the background colour
/// keeps it readable where it crosses lines.
struct MathPaint {
  Color color = palette::ink;
  bool halo = false;
  Color halo_color = palette::paper;
};

/// How far a halo reaches beyond the ink, in pixels.
double math_halo_reach(const MathPaint&, double scale);

/// Draws a laid-out box (layout_formula, layout_rich_text) with its origin
/// (the left end of its first baseline) at `origin`, in pixels: the halo
/// under everything first, then the glyphs, rules and strokes. On a
/// recording canvas every leaf's ink box (with the halo) goes into the
/// DrawingRecord's outline as OutlineKind::formula, named `name`, so the
/// label placer keeps labels off it; damage is noted as for any drawing.
/// Returns the ink box in pixels, halo included.
PixelRect draw_math(Canvas&, const MathBox&, const Point& origin, const MathPaint&, const std::string& name = {});

/// Parses, lays out and draws a formula in one go; returns the ink box.
/// Throws UsageError for bad LaTeX (parse_formula).
PixelRect draw_formula(Canvas&, const std::string& source, const Point& origin, const MathStyle&, const MathPaint&);

}  // namespace vibra::render
