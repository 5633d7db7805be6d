// How wide a run of text is and how far its ink reaches, as the browser's canvas measures it with the page's fonts.
#pragma once
#include <string>

namespace vibra::web {

/// A run's advance and its ink around the baseline's left end, in pixels
/// (the canvas's TextMetrics: actualBoundingBox*).
struct TextExtent {
  double advance = 0;
  double ink_left = 0, ink_right = 0;  ///< from the run's start, rightwards
  double ink_ascent = 0, ink_descent = 0;  ///< above and below the baseline
};

/// Measures `text` in `font` (a CSS font, e.g. "italic 18px 'DejaVu Sans'",
/// whose size in pixels is `size`).
using MeasureText = TextExtent (*)(const std::string& font, double size, const std::string& text);

/// The browser build measures with the page's canvas; a native build of
/// the backend (its tests) with fixed advances unless told otherwise.
MeasureText text_measure();
void set_text_measure(MeasureText measure);

/// DejaVu Sans's line, in ems (its hhea ascender 1901 and descender 483 of
/// 2048 units): what Pango's logical rectangle spans.
inline constexpr double kAscentEm = 1901.0 / 2048;
inline constexpr double kDescentEm = 483.0 / 2048;

/// The line's ascent and descent in whole pixels, as Pango has them on an
/// image surface (hinted metrics: FreeType rounds each up to a pixel), for a
/// font `size` pixels high. Pango's baseline is the ascent, its logical
/// height their sum: the fractional ems would set text and stack rows up to
/// a pixel off the native picture. The tolerance is FreeType's 26.6 fixed
/// point, which lands a hair under a whole pixel where the double is over.
int hinted_ascent(double size);
int hinted_descent(double size);

}  // namespace vibra::web
