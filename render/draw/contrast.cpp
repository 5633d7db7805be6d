// Contrast ratios and legible colours: WCAG 2 relative luminance, and a mix toward black or white that meets a ratio.
#include "render/draw/contrast.hpp"

#include <algorithm>
#include <cmath>

namespace vibra::render {

namespace {
double linear(double c) {
  c = std::clamp(c, 0.0, 1.0);
  return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

Color mixed(const Color& a, const Color& b, double w) {
  return {a.r + w * (b.r - a.r), a.g + w * (b.g - a.g), a.b + w * (b.b - a.b), a.a};
}
}  // namespace

double relative_luminance(const Color& c) {
  return 0.2126 * linear(c.r) + 0.7152 * linear(c.g) + 0.0722 * linear(c.b);
}

double contrast_ratio(const Color& a, const Color& b) {
  const double la = relative_luminance(a), lb = relative_luminance(b);
  return (std::max(la, lb) + 0.05) / (std::min(la, lb) + 0.05);
}

Color legible_on(const Color& ink, const Color& ground, double ratio) {
  if (contrast_ratio(ink, ground) >= ratio) return ink;
  ratio *= 1.02;  // a margin, so the colour still meets the ratio once stored in 8 bits a channel
  const double lg = relative_luminance(ground);
  const bool ink_lighter = relative_luminance(ink) >= lg;
  const Color white{1, 1, 1}, black{0, 0, 0};
  // Away from the ground first (lighter ink toward white), then the other
  // way. Along a mix toward a pole the luminance moves one way, so "meets
  // the ratio on the pole's side of the ground" turns true once and stays
  // true: bisection finds the least mix.
  const Color poles[2] = {ink_lighter ? white : black, ink_lighter ? black : white};
  for (const Color& pole : poles) {
    if (contrast_ratio(pole, ground) < ratio) continue;
    const bool toward_white = pole.r == 1;
    auto meets = [&](double w) {
      const Color c = mixed(ink, pole, w);
      return contrast_ratio(c, ground) >= ratio && (relative_luminance(c) > lg) == toward_white;
    };
    double lo = 0, hi = 1;
    for (int i = 0; i < 40; ++i) {
      const double w = 0.5 * (lo + hi);
      (meets(w) ? hi : lo) = w;
    }
    return mixed(ink, pole, hi);
  }
  return mixed(ink, lg > 0.18 ? black : white, 1);  // no colour meets the ratio on this ground: the best there is
}

}  // namespace vibra::render
