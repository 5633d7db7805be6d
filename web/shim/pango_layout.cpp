// The browser build's Pango: one-line layouts of styled runs, measured by the browser and drawn as its text runs.
#include <pango/pangocairo.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "web/canvas/text_measure.hpp"
#include "web/shim/cairo_context.hpp"
#include "web/shim/pango_markup.hpp"

struct _PangoFontDescription {
  std::string family = "DejaVu Sans";
  double size = 16;  ///< pixels
  bool italic = false, bold = false;
};

struct _PangoFontMap {};

namespace vibra::web::shim {

/// A glyph placed on the layout's line.
struct PlacedRun {
  std::string text, font;
  double x, rise, size;  ///< rise in pixels, upwards
  TextExtent extent;
};

}  // namespace vibra::web::shim

struct _PangoLayout {
  _PangoFontDescription font;
  std::vector<vibra::web::shim::MarkupRun> runs;
  double width = -1;  ///< pixels; negative: no limit
  bool ellipsize = false;
};

namespace {

using vibra::web::shim::PlacedRun;

std::string css_font(const _PangoFontDescription& f, const vibra::web::shim::RunStyle& s, double size) {
  std::string css = s.italic || f.italic ? "italic " : "";
  if (s.bold || f.bold) css += "bold ";
  char px[32];
  std::snprintf(px, sizeof px, "%.3fpx", size);
  return css + px + " '" + f.family + "'";
}

/// A text's extent, measured once per font (a frame sets the same few
/// labels again and again); the cache starts over past a bound.
vibra::web::TextExtent measured(const std::string& font, double size, const std::string& text) {
  static std::map<std::string, vibra::web::TextExtent> cache;
  constexpr std::size_t kMostTexts = 8192;
  const std::string key = font + '\0' + text;
  if (auto it = cache.find(key); it != cache.end()) return it->second;
  if (cache.size() >= kMostTexts) cache.clear();
  return cache[key] = vibra::web::text_measure()(font, size, text);
}

/// The byte after the UTF-8 character that starts at `i` of `text`.
std::size_t next_character(const std::string& text, std::size_t i) {
  std::size_t next = i + 1;
  while (next < text.size() && (static_cast<unsigned char>(text[next]) & 0xC0) == 0x80) ++next;
  return next;
}

/// The runs split into glyphs (one per UTF-8 character). As Pango on an
/// image surface (hinted metrics), each glyph advances a whole number of
/// pixels: its own advance with the kerning to the next glyph of its run
/// (harfbuzz puts a pair's kerning on the first glyph), rounded half up.
/// This gave native Pango's glyph positions for 128 texts at the page's
/// sizes; rounding the run's width up to each glyph instead set an 'r' or a
/// 'V' a pixel wider than Pango.
std::vector<PlacedRun> place(const _PangoLayout& layout, const std::vector<vibra::web::shim::MarkupRun>& runs) {
  std::vector<PlacedRun> placed;
  double x = 0;
  for (const auto& run : runs) {
    const double size = layout.font.size * run.style.scale;
    const std::string font = css_font(layout.font, run.style, size);
    for (std::size_t i = 0; i < run.text.size();) {
      const std::size_t next = next_character(run.text, i);
      PlacedRun p{run.text.substr(i, next - i), font, x, run.style.rise * layout.font.size, size, {}};
      p.extent = measured(font, size, p.text);
      double advance = p.extent.advance;
      if (next < run.text.size()) {
        const std::size_t after = next_character(run.text, next);
        advance = measured(font, size, run.text.substr(i, after - i)).advance -
                  measured(font, size, run.text.substr(next, after - next)).advance;
      }
      p.extent.advance = std::floor(advance + 0.5);
      x += p.extent.advance;
      placed.push_back(p);
      i = next;
    }
  }
  return placed;
}

double advance_of(const std::vector<PlacedRun>& runs) {
  return runs.empty() ? 0 : runs.back().x + runs.back().extent.advance;
}

/// Drops the last character of the runs (UTF-8 aware); false when none is left.
bool drop_last_character(std::vector<vibra::web::shim::MarkupRun>& runs) {
  while (!runs.empty() && runs.back().text.empty()) runs.pop_back();
  if (runs.empty()) return false;
  std::string& t = runs.back().text;
  std::size_t cut = t.size() - 1;
  while (cut > 0 && (static_cast<unsigned char>(t[cut]) & 0xC0) == 0x80) --cut;
  t.erase(cut);
  return true;
}

/// The layout's runs placed, ended with "…" where a width is set and the
/// text is wider (at most one removal per character of the text).
std::vector<PlacedRun> line_of(const _PangoLayout& layout) {
  std::vector<PlacedRun> placed = place(layout, layout.runs);
  if (!layout.ellipsize || layout.width < 0 || advance_of(placed) <= layout.width) return placed;
  auto runs = layout.runs;
  while (drop_last_character(runs)) {
    auto shortened = runs;
    shortened.push_back({"…", runs.empty() ? vibra::web::shim::RunStyle{} : runs.back().style});
    placed = place(layout, shortened);
    if (advance_of(placed) <= layout.width) return placed;
  }
  return place(layout, {{"…", {}}});
}

/// The line's ascent and descent in pixels, as Pango's: each run's font's
/// (whole pixels, hinted), moved by its rise; a superscript raises the line's
/// top, a subscript lowers its bottom. A line of no text has its font's.
std::array<double, 2> line_reach(const _PangoLayout& layout, const std::vector<PlacedRun>& runs) {
  if (runs.empty())
    return {double(vibra::web::hinted_ascent(layout.font.size)), double(vibra::web::hinted_descent(layout.font.size))};
  std::array<double, 2> reach{-1e300, -1e300};
  for (const PlacedRun& r : runs) {
    reach[0] = std::max(reach[0], vibra::web::hinted_ascent(r.size) + r.rise);
    reach[1] = std::max(reach[1], vibra::web::hinted_descent(r.size) - r.rise);
  }
  return reach;
}

double baseline_of(const _PangoLayout& layout) { return line_reach(layout, line_of(layout))[0]; }

/// Extents in pixels, as doubles: ink (x0 y0 x1 y1), then logical.
std::array<double, 8> extents_of(const _PangoLayout& layout) {
  const std::vector<PlacedRun> runs = line_of(layout);
  const auto [ascent, descent] = line_reach(layout, runs);
  const double baseline = ascent;
  std::array<double, 8> e{1e300, 1e300, -1e300, -1e300, 0, 0, advance_of(runs), ascent + descent};
  for (const PlacedRun& r : runs) {
    e[0] = std::min(e[0], r.x + r.extent.ink_left), e[2] = std::max(e[2], r.x + r.extent.ink_right);
    e[1] = std::min(e[1], baseline - r.rise - r.extent.ink_ascent);
    e[3] = std::max(e[3], baseline - r.rise + r.extent.ink_descent);
  }
  if (e[0] > e[2]) e[0] = e[1] = e[2] = e[3] = 0;  // no ink
  return e;
}

void set_rect(PangoRectangle* r, double x0, double y0, double x1, double y1, double unit) {
  if (r) *r = PangoRectangle{int(std::lround(x0 * unit)), int(std::lround(y0 * unit)),
                              int(std::lround((x1 - x0) * unit)), int(std::lround((y1 - y0) * unit))};
}

/// The runs of `layout` at the current point, filled now or laid on the path.
void draw_layout(cairo_t* cr, PangoLayout* layout, bool on_path) {
  const auto origin = vibra::web::shim::to_user(cr, cr->current.x, cr->current.y);
  const std::vector<PlacedRun> runs = line_of(*layout);
  const double baseline = line_reach(*layout, runs)[0];
  const auto& m = cr->state.pen.matrix;
  const bool upright = m[1] == 0 && m[2] == 0;
  for (const PlacedRun& r : runs) {
    double x = origin.x + r.x, y = origin.y + baseline - r.rise;
    if (on_path) {
      cr->path_text.push_back({m, x, y, r.font, r.text});  // outlines, as Pango's: where they fall
      continue;
    }
    if (upright) {  // Cairo 1.16's image compositor sets each glyph at whole device pixels
      const auto at = vibra::web::shim::to_device(cr, x, y);
      const auto whole = vibra::web::shim::to_user(cr, std::round(at.x), std::round(at.y));
      x = whole.x, y = whole.y;
    }
    if (cr->state.source.type == CAIRO_PATTERN_TYPE_SOLID)
      cr->target->commands.text(false, cr->state.pen, x, y, r.font, r.text);
  }
}

}  // namespace

extern "C" {

// The scene code unrefs only layouts.
void g_object_unref(gpointer object) { delete static_cast<PangoLayout*>(object); }

PangoFontDescription* pango_font_description_from_string(const char* family) {
  auto* f = new _PangoFontDescription;
  if (family && *family) f->family = family;
  return f;
}
void pango_font_description_free(PangoFontDescription* f) { delete f; }
void pango_font_description_set_absolute_size(PangoFontDescription* f, double size) { f->size = size / PANGO_SCALE; }
void pango_font_description_set_style(PangoFontDescription* f, PangoStyle s) { f->italic = s != PANGO_STYLE_NORMAL; }
void pango_font_description_set_weight(PangoFontDescription* f, PangoWeight w) { f->bold = w >= PANGO_WEIGHT_BOLD; }

void pango_layout_set_font_description(PangoLayout* l, const PangoFontDescription* f) { l->font = *f; }
void pango_layout_set_markup(PangoLayout* l, const char* markup, int length) {
  l->runs = vibra::web::shim::parse_markup(length < 0 ? std::string(markup) : std::string(markup, length));
}
void pango_layout_set_text(PangoLayout* l, const char* text, int length) {
  l->runs = {{length < 0 ? std::string(text) : std::string(text, length), {}}};
}
void pango_layout_set_width(PangoLayout* l, int width) { l->width = width < 0 ? -1 : double(width) / PANGO_SCALE; }
void pango_layout_set_ellipsize(PangoLayout* l, PangoEllipsizeMode mode) { l->ellipsize = mode != PANGO_ELLIPSIZE_NONE; }

void pango_layout_get_extents(PangoLayout* l, PangoRectangle* ink, PangoRectangle* logical) {
  const auto e = extents_of(*l);
  set_rect(ink, e[0], e[1], e[2], e[3], PANGO_SCALE);
  set_rect(logical, e[4], e[5], e[6], e[7], PANGO_SCALE);
}

void pango_layout_get_pixel_extents(PangoLayout* l, PangoRectangle* ink, PangoRectangle* logical) {
  const auto e = extents_of(*l);
  // As pango_extents_to_pixels: ink widened to whole pixels, logical rounded.
  set_rect(ink, std::floor(e[0]), std::floor(e[1]), std::ceil(e[2]), std::ceil(e[3]), 1);
  set_rect(logical, std::round(e[4]), std::round(e[5]), std::round(e[6]), std::round(e[7]), 1);
}

int pango_layout_get_baseline(PangoLayout* l) { return int(std::lround(baseline_of(*l) * PANGO_SCALE)); }

PangoFontMap* pango_cairo_font_map_get_default(void) {
  static _PangoFontMap map;
  return &map;
}
PangoLayout* pango_cairo_create_layout(cairo_t*) { return new _PangoLayout; }
void pango_cairo_update_layout(cairo_t*, PangoLayout*) {}
void pango_cairo_show_layout(cairo_t* cr, PangoLayout* layout) { draw_layout(cr, layout, false); }
void pango_cairo_layout_path(cairo_t* cr, PangoLayout* layout) { draw_layout(cr, layout, true); }

}  // extern "C"
