// Colour: RGBA values, parsing "#rrggbb", and a palette that reads well projected (Okabe-Ito).
#include "render/draw/color.hpp"

#include <cctype>
#include <stdexcept>

namespace vibra::render {

Color palette::series(size_t k) {
  // Sky blue comes late: faded, it is the default blue faded.
  const Color colors[] = {blue, vermillion, green, purple, orange, ink, sky, yellow};
  return colors[k % 8];
}

Color parse_color(const std::string& hex) {
  auto fail = [&] { return std::invalid_argument("colour '" + hex + "' is not #rrggbb or #rrggbbaa"); };
  if (hex.size() != 7 && hex.size() != 9) throw fail();
  if (hex[0] != '#') throw fail();
  double c[4] = {0, 0, 0, 1};
  for (size_t i = 1, k = 0; i < hex.size(); i += 2, ++k) {
    // std::stoi alone would take " f" and "-1": each of the two must be a hex digit.
    if (!std::isxdigit(static_cast<unsigned char>(hex[i])) || !std::isxdigit(static_cast<unsigned char>(hex[i + 1])))
      throw fail();
    std::size_t used = 0;
    int v = 0;
    try {
      v = std::stoi(hex.substr(i, 2), &used, 16);
    } catch (...) {
      throw fail();
    }
    if (used != 2) throw fail();
    c[k] = v / 255.0;
  }
  return {c[0], c[1], c[2], c[3]};
}

}  // namespace vibra::render
