// The browser build's Cairo surfaces and patterns: a recording surface for the page, image surfaces that only hold pixels.
#include <cstring>

#include "web/canvas/surface_commands.hpp"
#include "web/shim/cairo_context.hpp"

namespace {

cairo_surface_t* new_surface(cairo_surface_type_t type, double width, double height) {
  auto* s = new _cairo_surface;
  s->type = type;
  s->width = static_cast<int>(width);
  s->height = static_cast<int>(height);
  return s;
}

}  // namespace

namespace vibra::web {
DrawCommands& commands_of(cairo_surface_t* surface) { return surface->commands; }
int skipped_of(cairo_surface_t* surface) { return surface->skipped; }
}  // namespace vibra::web

extern "C" {

cairo_surface_t* cairo_recording_surface_create(cairo_content_t, const cairo_rectangle_t* extents) {
  return new_surface(CAIRO_SURFACE_TYPE_RECORDING, extents ? extents->width : 0, extents ? extents->height : 0);
}

int cairo_format_stride_for_width(cairo_format_t format, int width) {
  return format == CAIRO_FORMAT_A8 ? (width + 3) / 4 * 4 : 4 * width;
}

cairo_surface_t* cairo_image_surface_create(cairo_format_t format, int width, int height) {
  cairo_surface_t* s = new_surface(CAIRO_SURFACE_TYPE_IMAGE, width, height);
  s->stride = cairo_format_stride_for_width(format, width);
  s->own_pixels.assign(static_cast<std::size_t>(s->stride) * height, 0);
  s->pixels = s->own_pixels.data();
  return s;
}

cairo_surface_t* cairo_image_surface_create_for_data(unsigned char* data, cairo_format_t, int width, int height,
                                                     int stride) {
  cairo_surface_t* s = new_surface(CAIRO_SURFACE_TYPE_IMAGE, width, height);
  s->stride = stride;
  s->pixels = data;
  return s;
}

// Vector files are not written in the browser: these surfaces record, as the page's does.
cairo_surface_t* cairo_svg_surface_create(const char*, double width, double height) {
  return new_surface(CAIRO_SURFACE_TYPE_SVG, width, height);
}
cairo_surface_t* cairo_pdf_surface_create(const char*, double width, double height) {
  return new_surface(CAIRO_SURFACE_TYPE_PDF, width, height);
}

unsigned char* cairo_image_surface_get_data(cairo_surface_t* s) { return s->pixels; }
cairo_format_t cairo_image_surface_get_format(cairo_surface_t* s) {
  return s->type == CAIRO_SURFACE_TYPE_IMAGE ? CAIRO_FORMAT_ARGB32 : CAIRO_FORMAT_INVALID;
}
int cairo_image_surface_get_width(cairo_surface_t* s) { return s->width; }
int cairo_image_surface_get_height(cairo_surface_t* s) { return s->height; }
int cairo_image_surface_get_stride(cairo_surface_t* s) { return s->stride; }
cairo_surface_type_t cairo_surface_get_type(cairo_surface_t* s) { return s->type; }
cairo_status_t cairo_surface_status(cairo_surface_t*) { return CAIRO_STATUS_SUCCESS; }

void cairo_surface_destroy(cairo_surface_t* s) {
  if (!s || --s->references > 0) return;
  for (const auto& [data, destroy] : s->user_data)
    if (destroy) destroy(data);
  delete s;
}

void cairo_surface_finish(cairo_surface_t*) {}
void cairo_surface_flush(cairo_surface_t*) {}
void cairo_surface_mark_dirty(cairo_surface_t*) {}
void cairo_surface_get_device_offset(cairo_surface_t*, double* x, double* y) { *x = *y = 0; }
void cairo_surface_get_device_scale(cairo_surface_t*, double* x, double* y) { *x = *y = 1; }

cairo_status_t cairo_surface_set_user_data(cairo_surface_t* s, const cairo_user_data_key_t*, void* data,
                                           cairo_destroy_func_t destroy) {
  s->user_data.emplace_back(data, destroy);  // freed with the surface, as Cairo does
  return CAIRO_STATUS_SUCCESS;
}

cairo_status_t cairo_surface_write_to_png(cairo_surface_t*, const char*) { return CAIRO_STATUS_WRITE_ERROR; }

const char* cairo_status_to_string(cairo_status_t status) {
  return status == CAIRO_STATUS_SUCCESS ? "no error has occurred" : "an error occurred in the browser's drawing";
}

cairo_pattern_t* cairo_pattern_create_for_surface(cairo_surface_t* surface) {
  auto* p = new _cairo_pattern;
  p->type = CAIRO_PATTERN_TYPE_SURFACE;
  p->surface = surface;
  return p;
}
void cairo_pattern_destroy(cairo_pattern_t* p) { delete p; }
cairo_pattern_type_t cairo_pattern_get_type(cairo_pattern_t* p) { return p->type; }

cairo_status_t cairo_pattern_get_rgba(cairo_pattern_t* p, double* r, double* g, double* b, double* a) {
  if (p->type != CAIRO_PATTERN_TYPE_SOLID) return CAIRO_STATUS_PATTERN_TYPE_MISMATCH;
  *r = p->rgba[0], *g = p->rgba[1], *b = p->rgba[2], *a = p->rgba[3];
  return CAIRO_STATUS_SUCCESS;
}
void cairo_pattern_set_extend(cairo_pattern_t* p, cairo_extend_t extend) { p->extend = extend; }
void cairo_pattern_set_filter(cairo_pattern_t* p, cairo_filter_t filter) { p->filter = filter; }
void cairo_pattern_set_matrix(cairo_pattern_t* p, const cairo_matrix_t* m) {
  p->matrix = {m->xx, m->yx, m->xy, m->yy, m->x0, m->y0};
}

}  // extern "C"
