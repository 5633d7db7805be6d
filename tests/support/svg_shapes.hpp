// The shapes of an SVG that Cairo wrote, with their strokes and fills: what a drawing test reads to name the colour, width or dash that changed.
#pragma once
#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

#include "render/draw/color.hpp"

namespace vibra::test {

/// One <path> drawn (not a glyph's outline), as Cairo's SVG surface writes it.
struct SvgShape {
  std::string stroke, fill;  ///< "rgb(10%,10%,12%)", "" when none
  double width = 0, stroke_opacity = 1;
  std::string dasharray;     ///< "6.4,4.8", "" when solid
  bool curved = false;       ///< it has Bézier segments (C)
  std::vector<double> xy;    ///< every number of its path data, in order: x, y, x, y ...
  double x(size_t i) const { return xy.at(2 * i); }
  double y(size_t i) const { return xy.at(2 * i + 1); }
  size_t points() const { return xy.size() / 2; }
};

namespace svg {
inline std::string attribute(const std::string& tag, const std::string& name) {
  const auto at = tag.find(" " + name + "=\"");
  if (at == std::string::npos) return "";
  const auto begin = at + name.size() + 3;
  return tag.substr(begin, tag.find('"', begin) - begin);
}

/// A property of a style attribute, "stroke-width:2.2;" -> "2.2" ("" if absent).
inline std::string property(const std::string& style, const std::string& key) {
  const auto at = (";" + style).find(";" + key + ":");
  if (at == std::string::npos) return "";
  const auto begin = at + key.size() + 1;
  return style.substr(begin, style.find(';', begin) - begin);
}

inline std::vector<double> numbers(const std::string& path) {
  std::vector<double> out;
  for (const char* p = path.c_str(); *p;) {
    char* end;
    const double v = std::strtod(p, &end);
    if (end == p) ++p;
    else out.push_back(v), p = end;
  }
  return out;
}
}  // namespace svg

/// The drawn paths of an SVG in drawing order; glyph outlines (inside <symbol>) left out.
inline std::vector<SvgShape> svg_shapes(const std::string& text) {
  using namespace svg;
  std::vector<SvgShape> out;
  bool in_symbol = false;
  for (size_t at = text.find('<'); at != std::string::npos; at = text.find('<', at + 1)) {
    const std::string tag = text.substr(at, text.find('>', at) + 1 - at);
    if (tag.rfind("<symbol", 0) == 0) in_symbol = true;
    else if (tag.rfind("</symbol", 0) == 0) in_symbol = false;
    if (in_symbol || tag.rfind("<path", 0) != 0) continue;
    const std::string style = attribute(tag, "style"), d = attribute(tag, "d");
    SvgShape s;
    s.stroke = property(style, "stroke") == "none" ? "" : property(style, "stroke");
    s.fill = property(style, "fill") == "none" ? "" : property(style, "fill");
    const std::string width = property(style, "stroke-width"), opacity = property(style, "stroke-opacity");
    s.width = width.empty() ? 0 : std::stod(width);
    s.stroke_opacity = opacity.empty() ? 1 : std::stod(opacity);
    s.dasharray = property(style, "stroke-dasharray");
    s.curved = d.find('C') != std::string::npos;
    s.xy = numbers(d);
    out.push_back(s);
  }
  return out;
}

/// Whether Cairo's "rgb(84%,37%,0%)" is `c` (to the percent it prints).
inline bool same_colour(const std::string& rgb, const render::Color& c) {
  const auto v = svg::numbers(rgb);
  return v.size() == 3 && std::abs(v[0] - 100 * c.r) < 0.6 && std::abs(v[1] - 100 * c.g) < 0.6 &&
         std::abs(v[2] - 100 * c.b) < 0.6;
}

}  // namespace vibra::test
