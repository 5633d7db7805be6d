#include "render/text.hpp"

#include <pango/pangocairo.h>

#include <algorithm>
#include <cmath>
#include <memory>

namespace vibra::render {

namespace {
std::unique_ptr<PangoLayout, void (*)(void*)> make_layout(Canvas& canvas, const std::string& markup,
                                                          const TextStyle& style) {
  PangoLayout* layout = pango_cairo_create_layout(canvas.cr());
  PangoFontDescription* font = pango_font_description_from_string(style.family);
  pango_font_description_set_absolute_size(font, style.size * canvas.scale() * PANGO_SCALE);
  pango_layout_set_font_description(layout, font);
  pango_font_description_free(font);
  pango_layout_set_markup(layout, markup.c_str(), -1);
  if (style.max_width > 0) {
    pango_layout_set_width(layout, static_cast<int>(style.max_width * PANGO_SCALE));
    pango_layout_set_ellipsize(layout, PANGO_ELLIPSIZE_END);
  }
  return {layout, g_object_unref};
}

Point ink_size(PangoLayout* layout) {
  PangoRectangle logical;
  pango_layout_get_pixel_extents(layout, nullptr, &logical);
  return {logical.width, logical.height};
}
}  // namespace

void start_loading_fonts() { pango_cairo_font_map_get_default(); }

Point text_size(Canvas& canvas, const std::string& markup, const TextStyle& style) {
  return ink_size(make_layout(canvas, markup, style).get());
}

void draw_text(Canvas& canvas, const Point& at, const std::string& markup, const TextStyle& style, Anchor anchor) {
  auto layout = make_layout(canvas, markup, style);
  PangoRectangle ink, logical;
  pango_layout_get_pixel_extents(layout.get(), &ink, &logical);
  const Point size(logical.width, logical.height);  // as ink_size()
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
  cairo_t* cr = canvas.cr();
  const double x = std::round(at.x() - fx * size.x()), y = std::round(at.y() - fy * size.y());
  cairo_move_to(cr, x, y);
  if (style.halo) {
    cairo_save(cr);
    pango_cairo_layout_path(cr, layout.get());
    cairo_set_source_rgba(cr, style.halo_color.r, style.halo_color.g, style.halo_color.b, style.halo_color.a);
    cairo_set_line_width(cr, 5 * canvas.scale());
    cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
    canvas.stroke();
    cairo_restore(cr);
    cairo_move_to(cr, x, y);
  }
  // Glyphs may reach beyond the logical box (italics, accents): note both boxes.
  canvas.mark_drawn(x + std::min(ink.x, logical.x), y + std::min(ink.y, logical.y),
                    x + std::max(ink.x + ink.width, logical.x + logical.width),
                    y + std::max(ink.y + ink.height, logical.y + logical.height));
  cairo_set_source_rgba(cr, style.color.r, style.color.g, style.color.b, style.color.a);
  pango_cairo_show_layout(cr, layout.get());
  cairo_new_path(cr);
}

Point label_beyond(const Point& tip, const Point& direction, const Point& size, double gap) {
  const double n = direction.norm();
  const Point d = n > 1e-12 ? Point(direction / n) : Point(1, 0);
  // Distance from the box centre to its edge along d, so any direction clears the box.
  const double reach = std::min(std::abs(d.x()) > 1e-12 ? 0.5 * size.x() / std::abs(d.x()) : 1e300,
                                std::abs(d.y()) > 1e-12 ? 0.5 * size.y() / std::abs(d.y()) : 1e300);
  return tip + (gap + reach) * d;
}

}  // namespace vibra::render
