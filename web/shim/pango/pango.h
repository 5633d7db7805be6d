/* The browser build's <pango/pango.h>: the part of Pango's API the scene code calls, text measured by the browser (web/canvas/text_measure.hpp). */
#pragma once

#ifdef __cplusplus
extern "C" {
#endif

#define PANGO_SCALE 1024
#define PANGO_PIXELS(d) (((int)(d) + 512) >> 10)

typedef void* gpointer;
typedef struct _PangoLayout PangoLayout;
typedef struct _PangoFontDescription PangoFontDescription;
typedef struct _PangoFontMap PangoFontMap;
typedef struct _PangoRectangle { int x, y, width, height; } PangoRectangle;
typedef enum { PANGO_STYLE_NORMAL, PANGO_STYLE_OBLIQUE, PANGO_STYLE_ITALIC } PangoStyle;
typedef enum { PANGO_WEIGHT_NORMAL = 400, PANGO_WEIGHT_BOLD = 700 } PangoWeight;
typedef enum { PANGO_ELLIPSIZE_NONE, PANGO_ELLIPSIZE_START, PANGO_ELLIPSIZE_MIDDLE,
               PANGO_ELLIPSIZE_END } PangoEllipsizeMode;

void g_object_unref(gpointer object);

PangoFontDescription* pango_font_description_from_string(const char* family);
void pango_font_description_free(PangoFontDescription* desc);
void pango_font_description_set_absolute_size(PangoFontDescription* desc, double size);
void pango_font_description_set_style(PangoFontDescription* desc, PangoStyle style);
void pango_font_description_set_weight(PangoFontDescription* desc, PangoWeight weight);

void pango_layout_set_font_description(PangoLayout* layout, const PangoFontDescription* desc);
void pango_layout_set_markup(PangoLayout* layout, const char* markup, int length);
void pango_layout_set_text(PangoLayout* layout, const char* text, int length);
void pango_layout_set_width(PangoLayout* layout, int width);
void pango_layout_set_ellipsize(PangoLayout* layout, PangoEllipsizeMode mode);
void pango_layout_get_extents(PangoLayout* layout, PangoRectangle* ink, PangoRectangle* logical);
void pango_layout_get_pixel_extents(PangoLayout* layout, PangoRectangle* ink, PangoRectangle* logical);
int pango_layout_get_baseline(PangoLayout* layout);

#ifdef __cplusplus
}
#endif
