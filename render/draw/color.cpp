// Colour: RGBA values, parsing "#rrggbb", and a palette that reads well projected (Okabe-Ito).
#include "render/draw/color.hpp"

#include <stdexcept>

namespace vibra::render {

Color palette::series(size_t k) {
  // Sky blue comes late: faded, it is the default blue faded.
  const Color colors[] = {blue, vermillion, green, purple, orange, ink, sky, yellow};
  return colors[k % 8];
}

namespace {
/// 0..15 for a hex digit, -1 for anything else.
int hex_digit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}
}  // namespace

Color parse_color(const std::string& hex) {
  auto fail = [&] { return std::invalid_argument("colour '" + hex + "' is not #rrggbb or #rrggbbaa"); };
  if (hex.size() != 7 && hex.size() != 9) throw fail();
  if (hex[0] != '#') throw fail();
  double c[4] = {0, 0, 0, 1};
  for (size_t i = 1, k = 0; i < hex.size(); i += 2, ++k) {
    // Each of the two must be a hex digit (std::stoi alone would take " f" and "-1").
    const int high = hex_digit(hex[i]), low = hex_digit(hex[i + 1]);
    if (high < 0 || low < 0) throw fail();
    c[k] = (16 * high + low) / 255.0;
  }
  return {c[0], c[1], c[2], c[3]};
}

}  // namespace vibra::render
