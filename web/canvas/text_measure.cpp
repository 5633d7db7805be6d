// The text measure in use: the browser's canvas in the browser build, fixed advances in a native build of the backend.
#include "web/canvas/text_measure.hpp"

#include <cmath>

#ifdef __EMSCRIPTEN__
#include <emscripten.h>
#endif

namespace vibra::web {

namespace {

/// How far under a whole pixel FreeType's rounded ascent may land: checked
/// against Pango at every size from 5 to 80 px in steps of 0.037.
constexpr double kFixedPointSlack = 1e-3;

#ifdef __EMSCRIPTEN__
// The page's 2D context measures; its five numbers come back through the heap.
EM_JS(void, browser_measure, (const char* font, const char* text, double* out), {
  const ctx = Module.vibraMeasureContext ||
              (Module.vibraMeasureContext = document.createElement('canvas').getContext('2d'));
  ctx.font = UTF8ToString(font);
  const m = ctx.measureText(UTF8ToString(text));
  const values = [ m.width, -m.actualBoundingBoxLeft, m.actualBoundingBoxRight, m.actualBoundingBoxAscent,
                   m.actualBoundingBoxDescent ];
  for (let i = 0; i < 5; ++i) HEAPF64[(out >> 3) + i] = values[i];
});

TextExtent measure_in_browser(const std::string& font, double, const std::string& text) {
  double out[5];
  browser_measure(font.c_str(), text.c_str(), out);
  return {out[0], out[1], out[2], out[3], out[4]};
}
MeasureText current = measure_in_browser;
#else
/// Every character (UTF-8 lead byte) 0.6 em wide, ink from the baseline to
/// the cap height: numbers a test can work out by hand.
TextExtent fixed_advance(const std::string&, double size, const std::string& text) {
  int characters = 0;
  for (unsigned char c : text) characters += (c & 0xC0) != 0x80;
  const double advance = 0.6 * size * characters;
  return {advance, 0, advance, 0.73 * size, 0};
}
MeasureText current = fixed_advance;
#endif

}  // namespace

int hinted_ascent(double size) { return int(std::ceil(kAscentEm * size - kFixedPointSlack)); }
int hinted_descent(double size) { return int(std::ceil(kDescentEm * size - kFixedPointSlack)); }

MeasureText text_measure() { return current; }
void set_text_measure(MeasureText measure) { current = measure; }

}  // namespace vibra::web
