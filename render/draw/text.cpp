// Text set by Pango: markup laid out, measured and drawn at an anchor, sizes in 720p pixels.
#include "render/draw/text.hpp"

#include <pango/pangocairo.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string_view>
#include <utility>

#include "render/draw/contrast.hpp"
#include "render/draw/label_cache.hpp"
#include "render/labels/drawing_record.hpp"

namespace vibra::render {

namespace {
/// A new layout of the markup, set up for `cr` (the caller unrefs it).
PangoLayout* new_layout(cairo_t* cr, const std::string& markup, const TextStyle& style, double scale) {
  PangoLayout* layout = pango_cairo_create_layout(cr);
  PangoFontDescription* font = pango_font_description_from_string(style.family);
  pango_font_description_set_absolute_size(font, style.size * scale * PANGO_SCALE);
  pango_layout_set_font_description(layout, font);
  pango_font_description_free(font);
  pango_layout_set_markup(layout, markup.c_str(), -1);
  if (style.max_width > 0) {
    pango_layout_set_width(layout, static_cast<int>(style.max_width * PANGO_SCALE));
    pango_layout_set_ellipsize(layout, PANGO_ELLIPSIZE_END);
  }
  return layout;
}


/// The halo, then the text, with the layout's origin at (x, y).
void show_layout(cairo_t* cr, PangoLayout* layout, const TextStyle& style, double scale, double x, double y) {
  if (style.halo) {
    cairo_save(cr);
    cairo_move_to(cr, x, y);
    pango_cairo_layout_path(cr, layout);
    cairo_set_source_rgba(cr, style.halo_color.r, style.halo_color.g, style.halo_color.b, style.halo_color.a);
    cairo_set_line_width(cr, 2 * halo_reach(style, scale));
    cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
    cairo_stroke(cr);
    cairo_restore(cr);
  }
  cairo_move_to(cr, x, y);
  // On its halo a label reads whatever it is asked in: never fainter than 3:1 against it.
  const Color ink = style.halo ? legible_on(style.color, style.halo_color) : style.color;
  cairo_set_source_rgba(cr, ink.r, ink.g, ink.b, ink.a);
  pango_cairo_show_layout(cr, layout);
  cairo_new_path(cr);
}

/// The canvas's label cache, when labels may be pasted from it: an image
/// canvas drawing at whole pixels (kept images sit on the pixel grid).
LabelCache* pasting_cache(Canvas& canvas) {
  LabelCache* cache = canvas.labels();
  if (!cache) return nullptr;
  cairo_matrix_t m;
  cairo_get_matrix(canvas.cr(), &m);
  const bool whole_pixels = m.xx == 1 && m.yy == 1 && m.xy == 0 && m.yx == 0 && m.x0 == std::round(m.x0) &&
                            m.y0 == std::round(m.y0);
  return whole_pixels ? cache : nullptr;
}

/// Everything that decides a label's pixels, as one string: the numbers'
/// bytes, the family, then the markup (a frame looks up every label: no
/// formatting here).
std::string label_key(const std::string& markup, const TextStyle& s, double scale) {
  const double numbers[] = {s.size * scale, s.max_width,     s.color.r,      s.color.g,      s.color.b,     s.color.a,
                            double(s.halo), s.halo_color.r, s.halo_color.g, s.halo_color.b, s.halo_color.a};
  std::string key(reinterpret_cast<const char*>(numbers), sizeof numbers);
  key += s.family;
  key += '\0';
  key += markup;
  return key;
}

LabelCache::Label& cached_label(LabelCache& cache, Canvas& canvas, const std::string& markup, const TextStyle& style) {
  const std::string key = label_key(markup, style, canvas.scale());
  if (LabelCache::Label* kept = cache.find(key)) return *kept;
  LabelCache::Label label;
  label.layout.reset(new_layout(canvas.cr(), markup, style, canvas.scale()), g_object_unref);
  pango_layout_get_pixel_extents(label.layout.get(), &label.ink, &label.logical);
  return cache.keep(key, std::move(label));
}

/// The pixels a label covers from its layout's origin: glyphs may reach
/// beyond the logical box (italics, accents), and the halo beyond both.
struct LabelBox {
  int x0, y0, x1, y1;
};
LabelBox label_box(const PangoRectangle& ink, const PangoRectangle& logical, double reach) {
  const int pad = static_cast<int>(std::ceil(reach));
  return {std::min(ink.x, logical.x) - pad, std::min(ink.y, logical.y) - pad,
          std::max(ink.x + ink.width, logical.x + logical.width) + pad,
          std::max(ink.y + ink.height, logical.y + logical.height) + pad};
}

/// Makes a kept label's image; false if none could be made.
bool draw_image(Canvas& canvas, LabelCache::Label& label, const std::string& markup, const TextStyle& style) {
  const double scale = canvas.scale();
  const LabelBox box = label_box(label.ink, label.logical, halo_reach(style, scale) + 1);
  const int w = std::max(1, box.x1 - box.x0), h = std::max(1, box.y1 - box.y0);
  std::shared_ptr<cairo_surface_t> image(cairo_image_surface_create(CAIRO_FORMAT_ARGB32, w, h), cairo_surface_destroy);
  if (cairo_surface_status(image.get()) != CAIRO_STATUS_SUCCESS) return false;
  cairo_t* cr = cairo_create(image.get());
  // As the canvas's own context draws (see Canvas).
  cairo_set_antialias(cr, kShapeAntialias);
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
  std::shared_ptr<PangoLayout> layout = std::move(label.layout);
  if (layout)
    pango_cairo_update_layout(cr, layout.get());
  else
    layout.reset(new_layout(cr, markup, style, scale), g_object_unref);
  show_layout(cr, layout.get(), style, scale, -box.x0, -box.y0);
  const bool drawn = cairo_status(cr) == CAIRO_STATUS_SUCCESS;
  cairo_destroy(cr);
  if (!drawn) return false;
  cairo_surface_flush(image.get());
  label.image = std::move(image);
  label.x = box.x0, label.y = box.y0;
  canvas.labels()->count_image(std::size_t(w) * h * 4);
  return true;
}

/// Where a box of `size` goes so that `anchor` of it lies at `at`, in whole pixels.
Point placed(const Point& at, const Point& size, Anchor anchor) {
  double fx = 0.5, fy = 0.5;  // fraction of the box left of / above the anchor
  switch (anchor) {
    case Anchor::center: break;
    case Anchor::left: fx = 0; break;
    case Anchor::right: fx = 1; break;
    case Anchor::top: fy = 0; break;
    case Anchor::bottom: fy = 1; break;
    case Anchor::top_left: fx = 0, fy = 0; break;
    case Anchor::top_right: fx = 1, fy = 0; break;
    case Anchor::bottom_left: fx = 0, fy = 1; break;
    case Anchor::bottom_right: fx = 1, fy = 1; break;
  }
  return {std::round(at.x() - fx * size.x()), std::round(at.y() - fy * size.y())};
}
}  // namespace

void start_loading_fonts() { pango_cairo_font_map_get_default(); }

Point text_size(Canvas& canvas, const std::string& markup, const TextStyle& style) {
  if (LabelCache* cache = pasting_cache(canvas)) {
    const PangoRectangle& logical = cached_label(*cache, canvas, markup, style).logical;
    return {logical.width, logical.height};
  }
  PangoLayout* layout = new_layout(canvas.cr(), markup, style, canvas.scale());
  PangoRectangle logical;
  pango_layout_get_pixel_extents(layout, nullptr, &logical);
  g_object_unref(layout);
  return {logical.width, logical.height};
}

namespace {
Point draw_text_unrecorded(Canvas& canvas, const Point& at, const std::string& markup, const TextStyle& style,
                           Anchor anchor) {
  cairo_t* cr = canvas.cr();
  const double scale = canvas.scale();
  LabelCache* cache = pasting_cache(canvas);
  LabelCache::Label* label = cache ? &cached_label(*cache, canvas, markup, style) : nullptr;
  if (label && (label->image || draw_image(canvas, *label, markup, style))) {
    const Point origin = placed(at, {label->logical.width, label->logical.height}, anchor);
    const double x = origin.x() + label->x, y = origin.y() + label->y;
    const int w = cairo_image_surface_get_width(label->image.get()), h = cairo_image_surface_get_height(label->image.get());
    canvas.mark_drawn(x, y, x + w, y + h);
    cairo_set_source_surface(cr, label->image.get(), x, y);
    cairo_rectangle(cr, x, y, w, h);
    cairo_fill(cr);
    return {label->logical.width, label->logical.height};
  }
  // Drawn directly: a vector canvas (or no memory for an image).
  std::shared_ptr<PangoLayout> layout(new_layout(cr, markup, style, scale), g_object_unref);
  PangoRectangle ink, logical;
  pango_layout_get_pixel_extents(layout.get(), &ink, &logical);
  const Point origin = placed(at, {logical.width, logical.height}, anchor);
  const LabelBox box = label_box(ink, logical, halo_reach(style, scale));
  canvas.mark_drawn(origin.x() + box.x0, origin.y() + box.y0, origin.x() + box.x1, origin.y() + box.y1);
  show_layout(cr, layout.get(), style, scale, origin.x(), origin.y());
  return {logical.width, logical.height};
}
}  // namespace

Point draw_text(Canvas& canvas, const Point& at, const std::string& markup, const TextStyle& style, Anchor anchor) {
  const Point size = draw_text_unrecorded(canvas, at, markup, style, anchor);
  if (DrawingRecord* record = canvas.record()) {
    // Its logical box and halo: what a placed label must keep off.
    const double reach = halo_reach(style, canvas.scale());
    const Point origin = placed(at, size, anchor);
    record->outline.add_box({origin.x() - reach, origin.y() - reach, size.x() + 2 * reach, size.y() + 2 * reach},
                            OutlineKind::text, markup);
  }
  return size;
}

double halo_reach(const TextStyle& style, double scale) { return style.halo ? 2.5 * scale : 0; }

LabelRay label_ray(const Point& direction, const Point& size) {
  const double n = direction.norm();
  const Point d = n > 1e-12 ? Point(direction / n) : Point(1, 0);
  // Distance from the box centre to its edge along d, so any direction clears the box.
  const double reach = std::min(std::abs(d.x()) > 1e-12 ? 0.5 * size.x() / std::abs(d.x()) : 1e300,
                                std::abs(d.y()) > 1e-12 ? 0.5 * size.y() / std::abs(d.y()) : 1e300);
  return {d, reach};
}

Point label_beyond(const Point& tip, const Point& direction, const Point& size, double gap) {
  return label_beyond(tip, label_ray(direction, size), gap);
}

std::string markup_plain_text(const std::string& markup) {
  std::string out;
  bool in_tag = false;
  for (char c : markup) {
    if (c == '<') in_tag = true;
    else if (c == '>') in_tag = false;
    else if (!in_tag) out += c;
  }
  for (const auto& [entity, c] : {std::pair{"&lt;", '<'}, {"&gt;", '>'}, {"&amp;", '&'}})
    for (size_t at = 0; (at = out.find(entity, at)) != std::string::npos; ++at)
      out.replace(at, std::string_view(entity).size(), 1, c);
  return out;
}

}  // namespace vibra::render
