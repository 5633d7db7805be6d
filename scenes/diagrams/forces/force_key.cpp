// The forces' key: each force's colour beside its name ("mg gravity").
#include "scenes/diagrams/forces/force_key.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "render/draw/elements/shapes.hpp"
#include "render/draw/text.hpp"

namespace vibra::scenes {

namespace {
constexpr double kShortest = 30, kLongest = 75;  ///< 720p pixels of the key's arrow
constexpr double kNameArrow = 18, kNameGap = 5, kEntryGap = 16, kNameRow = 22;  ///< 720p pixels of the names' rows
constexpr double kTextSize = 15;

/// The names' rows: for each entry, its row and its left edge (from the key's left).
struct NameSpot {
  int row;
  double x;
};
std::vector<NameSpot> name_spots(render::Canvas& canvas, const ForceKey& key, double width) {
  const double scale = canvas.scale();
  std::vector<NameSpot> spots;
  int row = 0;
  double x = 0;
  for (const ForceName& n : key.names) {
    const double w = (kNameArrow + kNameGap) * scale + render::text_size(canvas, n.name, {kTextSize}).x();
    if (x > 0 && x + w > width) ++row, x = 0;
    spots.push_back({row, x});
    x += w + kEntryGap * scale;
  }
  return spots;
}

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

/// What follows the scale's arrow: "= 2 mg", and "   (note)" when the note goes on that line.
std::string scale_text(const ForceKey& key, double f, bool with_note) {
  std::string text = "= " + value_text(f) + (key.unit.empty() ? "" : " " + key.unit);
  if (with_note && !key.note.empty()) text += "   (" + key.note + ")";
  return text;
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

bool force_note_fits(render::Canvas& canvas, const ForceKey& key, double pixels_per_world, double width) {
  if (key.note.empty()) return true;
  // The longest arrow and a character more: the diagram's final zoom (after
  // the rows are taken) may round the force to another value.
  const double scale = canvas.scale(), f = force_key_value(key, pixels_per_world, scale);
  const render::TextStyle style{kTextSize};
  const double line = render::text_size(canvas, "force scale", style).x() + (8 + kLongest + 6 + 10) * scale +
                      render::text_size(canvas, scale_text(key, f, true), style).x();
  return line <= width;
}

double force_key_rows_height(render::Canvas& canvas, const ForceKey& key, double width, bool note_row) {
  const int names = key.names.empty() ? 0 : name_spots(canvas, key, width).back().row + 1;
  return (names + note_row) * kNameRow * canvas.scale();
}

double draw_force_key(render::Canvas& canvas, const ForceKey& key, double pixels_per_world,
                      const render::Point& bottom_left, double width, bool note_row, const render::Color& ink) {
  const double scale = canvas.scale();
  const double f = force_key_value(key, pixels_per_world, scale);
  if (f <= 0) return 0;
  const render::TextStyle style{kTextSize, ink};
  const std::string text = scale_text(key, f, !note_row);
  const render::Point size = render::text_size(canvas, "force scale " + text, style);
  const double y = bottom_left.y() - 0.5 * size.y();
  const double length = f * key.world_per_force * pixels_per_world;
  double x = bottom_left.x();
  x += render::draw_text(canvas, {x, y}, "force scale", style, render::Anchor::left).x() + 8 * scale;
  render::draw_pixel_arrow(canvas, {x, y}, {x + length, y}, {ink, 2.2}, 12);
  x += length + 6 * scale;
  render::draw_text(canvas, {x, y}, text, style, render::Anchor::left);
  // The note in a row of its own above the scale's line where it does not fit beside it.
  const double rows = force_key_rows_height(canvas, key, width, note_row);
  if (note_row)
    render::draw_text(canvas, {bottom_left.x(), bottom_left.y() - size.y() - 0.5 * kNameRow * scale},
                      "(" + key.note + ")", style, render::Anchor::left);
  // The names in rows above those, each after an arrow in its colour.
  const std::vector<NameSpot> spots = name_spots(canvas, key, width);
  const double top = bottom_left.y() - size.y() - rows;
  for (size_t i = 0; i < spots.size(); ++i) {
    const double row_y = top + (spots[i].row + 0.5) * kNameRow * scale, left = bottom_left.x() + spots[i].x;
    render::draw_pixel_arrow(canvas, {left, row_y}, {left + kNameArrow * scale, row_y}, {key.names[i].color, 2.6}, 9);
    render::draw_text(canvas, {left + (kNameArrow + kNameGap) * scale, row_y}, key.names[i].name, style,
                      render::Anchor::left);
  }
  return size.y() + rows;
}

}  // namespace vibra::scenes
