/* The browser build's <cairo.h>: the part of Cairo's API the scene code calls, recorded as 2D-canvas operations (web/canvas/). */
#pragma once
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* The same names and numbers as Cairo 1.16, so that code written for Cairo
 * compiles unchanged; only what the scene code uses. */
typedef int cairo_bool_t;
typedef struct _cairo cairo_t;
typedef struct _cairo_surface cairo_surface_t;
typedef struct _cairo_pattern cairo_pattern_t;
typedef struct _cairo_user_data_key { int unused; } cairo_user_data_key_t;
typedef void (*cairo_destroy_func_t)(void* data);

typedef enum _cairo_status { CAIRO_STATUS_SUCCESS = 0, CAIRO_STATUS_NO_MEMORY, CAIRO_STATUS_INVALID_RESTORE,
                             CAIRO_STATUS_INVALID_POP_GROUP, CAIRO_STATUS_NO_CURRENT_POINT,
                             CAIRO_STATUS_INVALID_MATRIX, CAIRO_STATUS_INVALID_STATUS, CAIRO_STATUS_NULL_POINTER,
                             CAIRO_STATUS_INVALID_STRING, CAIRO_STATUS_INVALID_PATH_DATA,
                             CAIRO_STATUS_READ_ERROR, CAIRO_STATUS_WRITE_ERROR, CAIRO_STATUS_SURFACE_FINISHED,
                             CAIRO_STATUS_SURFACE_TYPE_MISMATCH, CAIRO_STATUS_PATTERN_TYPE_MISMATCH,
                             CAIRO_STATUS_INVALID_CONTENT, CAIRO_STATUS_INVALID_FORMAT,
                             CAIRO_STATUS_INVALID_VISUAL, CAIRO_STATUS_FILE_NOT_FOUND,
                             CAIRO_STATUS_INVALID_DASH } cairo_status_t;
typedef enum _cairo_format { CAIRO_FORMAT_INVALID = -1, CAIRO_FORMAT_ARGB32 = 0, CAIRO_FORMAT_RGB24 = 1,
                             CAIRO_FORMAT_A8 = 2 } cairo_format_t;
typedef enum _cairo_content { CAIRO_CONTENT_COLOR = 0x1000, CAIRO_CONTENT_ALPHA = 0x2000,
                              CAIRO_CONTENT_COLOR_ALPHA = 0x3000 } cairo_content_t;
typedef enum _cairo_antialias { CAIRO_ANTIALIAS_DEFAULT, CAIRO_ANTIALIAS_NONE, CAIRO_ANTIALIAS_GRAY,
                                CAIRO_ANTIALIAS_SUBPIXEL, CAIRO_ANTIALIAS_FAST, CAIRO_ANTIALIAS_GOOD,
                                CAIRO_ANTIALIAS_BEST } cairo_antialias_t;
typedef enum _cairo_line_join { CAIRO_LINE_JOIN_MITER, CAIRO_LINE_JOIN_ROUND, CAIRO_LINE_JOIN_BEVEL } cairo_line_join_t;
typedef enum _cairo_line_cap { CAIRO_LINE_CAP_BUTT, CAIRO_LINE_CAP_ROUND, CAIRO_LINE_CAP_SQUARE } cairo_line_cap_t;
typedef enum _cairo_fill_rule { CAIRO_FILL_RULE_WINDING, CAIRO_FILL_RULE_EVEN_ODD } cairo_fill_rule_t;
typedef enum _cairo_operator { CAIRO_OPERATOR_CLEAR, CAIRO_OPERATOR_SOURCE, CAIRO_OPERATOR_OVER } cairo_operator_t;
typedef enum _cairo_surface_type { CAIRO_SURFACE_TYPE_IMAGE = 0, CAIRO_SURFACE_TYPE_PDF = 1,
                                   CAIRO_SURFACE_TYPE_SVG = 10, CAIRO_SURFACE_TYPE_RECORDING = 16 } cairo_surface_type_t;
typedef enum _cairo_pattern_type { CAIRO_PATTERN_TYPE_SOLID, CAIRO_PATTERN_TYPE_SURFACE } cairo_pattern_type_t;
typedef enum _cairo_extend { CAIRO_EXTEND_NONE, CAIRO_EXTEND_REPEAT, CAIRO_EXTEND_REFLECT,
                             CAIRO_EXTEND_PAD } cairo_extend_t;
typedef enum _cairo_filter { CAIRO_FILTER_FAST, CAIRO_FILTER_GOOD, CAIRO_FILTER_BEST, CAIRO_FILTER_NEAREST,
                             CAIRO_FILTER_BILINEAR, CAIRO_FILTER_GAUSSIAN } cairo_filter_t;
typedef enum _cairo_path_data_type { CAIRO_PATH_MOVE_TO, CAIRO_PATH_LINE_TO, CAIRO_PATH_CURVE_TO,
                                     CAIRO_PATH_CLOSE_PATH } cairo_path_data_type_t;

typedef struct _cairo_matrix { double xx, yx, xy, yy, x0, y0; } cairo_matrix_t;
typedef struct _cairo_rectangle { double x, y, width, height; } cairo_rectangle_t;
typedef struct _cairo_rectangle_list {
  cairo_status_t status;
  cairo_rectangle_t* rectangles;
  int num_rectangles;
} cairo_rectangle_list_t;
typedef union _cairo_path_data_t {
  struct { cairo_path_data_type_t type; int length; } header;
  struct { double x, y; } point;
} cairo_path_data_t;
typedef struct cairo_path {
  cairo_status_t status;
  cairo_path_data_t* data;
  int num_data;
} cairo_path_t;

/* Surfaces: a recording surface is what the page draws on (its operations
 * are read by web/canvas/surface_commands.hpp); an image surface holds
 * pixels that nothing rasterizes into here, so the scene code's image-only
 * paths (pasted label tiles, the software stroke) must not be taken. */
cairo_surface_t* cairo_recording_surface_create(cairo_content_t content, const cairo_rectangle_t* extents);
cairo_surface_t* cairo_image_surface_create(cairo_format_t format, int width, int height);
cairo_surface_t* cairo_image_surface_create_for_data(unsigned char* data, cairo_format_t format, int width,
                                                     int height, int stride);
cairo_surface_t* cairo_svg_surface_create(const char* filename, double width, double height);
cairo_surface_t* cairo_pdf_surface_create(const char* filename, double width, double height);
int cairo_format_stride_for_width(cairo_format_t format, int width);
unsigned char* cairo_image_surface_get_data(cairo_surface_t* surface);
cairo_format_t cairo_image_surface_get_format(cairo_surface_t* surface);
int cairo_image_surface_get_width(cairo_surface_t* surface);
int cairo_image_surface_get_height(cairo_surface_t* surface);
int cairo_image_surface_get_stride(cairo_surface_t* surface);
cairo_surface_type_t cairo_surface_get_type(cairo_surface_t* surface);
cairo_status_t cairo_surface_status(cairo_surface_t* surface);
void cairo_surface_destroy(cairo_surface_t* surface);
void cairo_surface_finish(cairo_surface_t* surface);
void cairo_surface_flush(cairo_surface_t* surface);
void cairo_surface_mark_dirty(cairo_surface_t* surface);
void cairo_surface_get_device_offset(cairo_surface_t* surface, double* x_offset, double* y_offset);
void cairo_surface_get_device_scale(cairo_surface_t* surface, double* x_scale, double* y_scale);
cairo_status_t cairo_surface_set_user_data(cairo_surface_t* surface, const cairo_user_data_key_t* key, void* data,
                                           cairo_destroy_func_t destroy);
cairo_status_t cairo_surface_write_to_png(cairo_surface_t* surface, const char* filename);
const char* cairo_status_to_string(cairo_status_t status);

/* Contexts: state, paths, drawing. */
cairo_t* cairo_create(cairo_surface_t* target);
void cairo_destroy(cairo_t* cr);
cairo_status_t cairo_status(cairo_t* cr);
void cairo_save(cairo_t* cr);
void cairo_restore(cairo_t* cr);
void cairo_push_group(cairo_t* cr);
void cairo_pop_group_to_source(cairo_t* cr);
cairo_surface_t* cairo_get_group_target(cairo_t* cr);
void cairo_set_source_rgb(cairo_t* cr, double red, double green, double blue);
void cairo_set_source_rgba(cairo_t* cr, double red, double green, double blue, double alpha);
void cairo_set_source_surface(cairo_t* cr, cairo_surface_t* surface, double x, double y);
void cairo_set_source(cairo_t* cr, cairo_pattern_t* source);
cairo_pattern_t* cairo_get_source(cairo_t* cr);
void cairo_set_operator(cairo_t* cr, cairo_operator_t op);
cairo_operator_t cairo_get_operator(cairo_t* cr);
void cairo_set_antialias(cairo_t* cr, cairo_antialias_t antialias);
cairo_antialias_t cairo_get_antialias(cairo_t* cr);
void cairo_set_line_width(cairo_t* cr, double width);
double cairo_get_line_width(cairo_t* cr);
void cairo_set_line_join(cairo_t* cr, cairo_line_join_t join);
cairo_line_join_t cairo_get_line_join(cairo_t* cr);
void cairo_set_line_cap(cairo_t* cr, cairo_line_cap_t cap);
cairo_line_cap_t cairo_get_line_cap(cairo_t* cr);
void cairo_set_dash(cairo_t* cr, const double* dashes, int num_dashes, double offset);
int cairo_get_dash_count(cairo_t* cr);
void cairo_get_dash(cairo_t* cr, double* dashes, double* offset);
void cairo_translate(cairo_t* cr, double tx, double ty);
void cairo_identity_matrix(cairo_t* cr);
void cairo_get_matrix(cairo_t* cr, cairo_matrix_t* matrix);
void cairo_user_to_device(cairo_t* cr, double* x, double* y);
void cairo_user_to_device_distance(cairo_t* cr, double* dx, double* dy);
void cairo_device_to_user(cairo_t* cr, double* x, double* y);
void cairo_matrix_init_translate(cairo_matrix_t* matrix, double tx, double ty);

void cairo_new_path(cairo_t* cr);
void cairo_new_sub_path(cairo_t* cr);
void cairo_move_to(cairo_t* cr, double x, double y);
void cairo_line_to(cairo_t* cr, double x, double y);
void cairo_close_path(cairo_t* cr);
void cairo_rectangle(cairo_t* cr, double x, double y, double width, double height);
void cairo_arc(cairo_t* cr, double xc, double yc, double radius, double angle1, double angle2);
void cairo_arc_negative(cairo_t* cr, double xc, double yc, double radius, double angle1, double angle2);
void cairo_path_extents(cairo_t* cr, double* x1, double* y1, double* x2, double* y2);
cairo_path_t* cairo_copy_path_flat(cairo_t* cr);
void cairo_path_destroy(cairo_path_t* path);

void cairo_stroke(cairo_t* cr);
void cairo_fill(cairo_t* cr);
void cairo_fill_preserve(cairo_t* cr);
void cairo_clip(cairo_t* cr);
void cairo_clip_extents(cairo_t* cr, double* x1, double* y1, double* x2, double* y2);
cairo_rectangle_list_t* cairo_copy_clip_rectangle_list(cairo_t* cr);
void cairo_rectangle_list_destroy(cairo_rectangle_list_t* list);
void cairo_paint(cairo_t* cr);
void cairo_paint_with_alpha(cairo_t* cr, double alpha);

/* Patterns: a solid colour, or a surface (recorded as not drawn). */
cairo_pattern_t* cairo_pattern_create_for_surface(cairo_surface_t* surface);
void cairo_pattern_destroy(cairo_pattern_t* pattern);
cairo_pattern_type_t cairo_pattern_get_type(cairo_pattern_t* pattern);
cairo_status_t cairo_pattern_get_rgba(cairo_pattern_t* pattern, double* red, double* green, double* blue,
                                      double* alpha);
void cairo_pattern_set_extend(cairo_pattern_t* pattern, cairo_extend_t extend);
void cairo_pattern_set_filter(cairo_pattern_t* pattern, cairo_filter_t filter);
void cairo_pattern_set_matrix(cairo_pattern_t* pattern, const cairo_matrix_t* matrix);

#ifdef __cplusplus
}
#endif
