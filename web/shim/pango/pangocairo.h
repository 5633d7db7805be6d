/* The browser build's <pango/pangocairo.h>: layouts set on a context of web/shim/cairo.h, drawn as the browser's text runs. */
#pragma once
#include <cairo.h>
#include <pango/pango.h>

#ifdef __cplusplus
extern "C" {
#endif

PangoFontMap* pango_cairo_font_map_get_default(void);
PangoLayout* pango_cairo_create_layout(cairo_t* cr);
void pango_cairo_update_layout(cairo_t* cr, PangoLayout* layout);
void pango_cairo_show_layout(cairo_t* cr, PangoLayout* layout);
void pango_cairo_layout_path(cairo_t* cr, PangoLayout* layout);

#ifdef __cplusplus
}
#endif
