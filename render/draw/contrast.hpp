// Contrast between two colours as a viewer sees it (WCAG 2 ratio), and the nearest colour of a hue that reads on a ground.
#pragma once
#include "render/draw/color.hpp"

namespace vibra::render {

/// The least contrast a mark (arrow, label) keeps against what it sits on:
/// WCAG 2's floor for graphics and large text, what still reads projected.
inline constexpr double kLegibleContrast = 3.0;

/// Relative luminance of an opaque colour (sRGB, WCAG 2 definition), 0 to 1.
double relative_luminance(const Color&);

/// (L_lighter + 0.05) / (L_darker + 0.05): 1 for equal colours, 21 for black on white.
double contrast_ratio(const Color&, const Color&);

/// `ink` itself when it keeps `ratio` against `ground`; otherwise the least
/// mix of it toward black (on a light ground) or white (on a dark one) that
/// does, so a mark keeps its hue and is never lost on its ground. Alpha kept.
Color legible_on(const Color& ink, const Color& ground, double ratio = kLegibleContrast);

}  // namespace vibra::render
