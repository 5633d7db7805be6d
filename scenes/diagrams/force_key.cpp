#include "scenes/diagrams/force_key.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "render/draw/shapes.hpp"
#include "render/draw/text.hpp"

namespace vibra::scenes {

namespace {
constexpr double kShortest = 30, kLongest = 75;  ///< 720p pixels of the key's arrow

std::string value_text(double f) {
  char text[48];
  std::snprintf(text, sizeof text, "%g", f);
  std::string s = text;
  const size_t e = s.find('e');
  if (e == std::string::npos) return s;
  // 1e-05 -> 10<sup>−5</sup>, 2e+06 -> 2·10<sup>6</sup>
  const int power = std::atoi(s.c_str() + e + 1);
  const std::string mantissa = s.substr(0, e);
  std::string exponent = std::to_string(std::abs(power));
  if (power < 0) exponent = "\u2212" + exponent;
  return (mantissa == "1" ? std::string() : mantissa + "·") + "10<sup>" + exponent + "</sup>";
}
}  // namespace

double force_key_value(const ForceKey& key, double pixels_per_world, double scale) {
  const double pixels_per_force = key.world_per_force * pixels_per_world;
  if (!(pixels_per_force > 0) || !std::isfinite(pixels_per_force) || !(scale > 0)) return 0;
  // The largest round force whose arrow is at most kLongest; it is at least
  // kLongest / 2.5 >= kShortest since round numbers are at most 2.5 apart.
  const double most = kLongest * scale / pixels_per_force;
  const double power = std::pow(10, std::floor(std::log10(most)));
  if (!std::isfinite(power) || power <= 0) return 0;
  for (double m : {5.0, 2.0, 1.0})
    if (m * power <= most * (1 + 1e-12)) return m * power;
  return power;
}

double draw_force_key(render::Canvas& canvas, const ForceKey& key, double pixels_per_world,
                      const render::Point& bottom_left, const render::Color& ink) {
  const double scale = canvas.scale();
  const double f = force_key_value(key, pixels_per_world, scale);
  if (f <= 0) return 0;
  const render::TextStyle style{15, ink};
  std::string text = "= " + value_text(f) + (key.unit.empty() ? "" : " " + key.unit);
  if (!key.note.empty()) text += "   (" + key.note + ")";
  const render::Point size = render::text_size(canvas, "force scale " + text, style);
  const double y = bottom_left.y() - 0.5 * size.y();
  const double length = f * key.world_per_force * pixels_per_world;
  double x = bottom_left.x();
  x += render::draw_text(canvas, {x, y}, "force scale", style, render::Anchor::left).x() + 8 * scale;
  render::draw_pixel_arrow(canvas, {x, y}, {x + length, y}, {ink, 2.2}, 12);
  x += length + 6 * scale;
  render::draw_text(canvas, {x, y}, text, style, render::Anchor::left);
  return size.y();
}

}  // namespace vibra::scenes
