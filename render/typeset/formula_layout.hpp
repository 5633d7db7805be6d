// Lays out a parsed formula into boxes, with TeX's spacing, sizes and fractions.
#pragma once
#include <string>
#include <vector>

#include "render/draw/canvas.hpp"
#include "render/typeset/formula_parser.hpp"
#include "render/typeset/math_box.hpp"

namespace vibra::render {

/// How a formula is set: its em in 720p pixels (multiplied by the canvas's
/// scale, as labels are), in the family the labels use.
struct MathStyle {
  double size = 22;
  const char* family = "DejaVu Sans";
  bool bold_text = false;  ///< words (rich text, \text) in bold: a title
};

/// Lays out a parsed formula with Pango's metrics for `canvas` (its scale
/// sets the pixels, its Cairo context the font options): TeX's spacing
/// between atoms, scripts raised and lowered by TeX's rules, fractions on
/// the math axis, delimiters and radicals sized to their content. Lines
/// (\\) are stacked, left-aligned; the origin is the first line's baseline.
MathBox layout_formula(Canvas&, const Formula&, const MathStyle&);

/// Text with math runs (parse_rich_text): words set upright, formulas as
/// layout_formula sets them, broken between words onto lines at most
/// `max_width` pixels wide (0: one line). The origin is the first line's baseline.
MathBox layout_rich_text(Canvas&, const std::vector<RichRun>&, const MathStyle&, double max_width = 0);

}  // namespace vibra::render
