// The browser build's Cairo objects: a surface with its recorded operations, a context's drawing state and path.
#pragma once
#include <cairo.h>

#include <array>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "web/canvas/draw_commands.hpp"

struct _cairo_surface {
  cairo_surface_type_t type = CAIRO_SURFACE_TYPE_RECORDING;
  int width = 0, height = 0, stride = 0;
  std::vector<unsigned char> own_pixels;  ///< an image surface's, unless it was given them
  unsigned char* pixels = nullptr;
  vibra::web::DrawCommands commands;
  /// Operations the 2D canvas is not handed (a surface as a source): the
  /// tests hold scenes to none.
  int skipped = 0;
  int references = 1;
  std::vector<std::pair<void*, cairo_destroy_func_t>> user_data;
};

struct _cairo_pattern {
  cairo_pattern_type_t type = CAIRO_PATTERN_TYPE_SOLID;
  std::array<double, 4> rgba{0, 0, 0, 1};
  cairo_surface_t* surface = nullptr;  ///< a surface pattern's (not owned: the scene code keeps it)
  std::array<double, 6> matrix{1, 0, 0, 1, 0, 0};  ///< user space to the surface's pixels, as Cairo's
  cairo_extend_t extend = CAIRO_EXTEND_NONE;
  cairo_filter_t filter = CAIRO_FILTER_GOOD;
};

namespace vibra::web::shim {

struct DevicePoint {
  double x, y;
};

/// What cairo_save keeps and cairo_restore brings back.
struct GraphicsState {
  Pen pen;  ///< colour, width, join, cap, dashes, and the user matrix
  _cairo_pattern source;
  /// The user matrix when the source was set: Cairo locks a pattern to the
  /// user space of that moment.
  std::array<double, 6> source_user{1, 0, 0, 1, 0, 0};
  bool group_source = false;  ///< the source is a popped group
  cairo_operator_t op = CAIRO_OPERATOR_OVER;
  cairo_antialias_t antialias = CAIRO_ANTIALIAS_DEFAULT;
  std::array<double, 4> clip{-1e9, -1e9, 1e9, 1e9};  ///< device box: x0 y0 x1 y1
};

/// A run of text added to the path by pango_cairo_layout_path: drawn as
/// text by the stroke or fill that follows.
struct PathText {
  std::array<double, 6> matrix;
  double x, y;
  std::string font, text;
};

/// A subpath in device pixels; arcs are already flattened into lines.
struct Subpath {
  std::vector<DevicePoint> points;
  bool closed = false;
};

}  // namespace vibra::web::shim

struct _cairo {
  cairo_surface_t* target = nullptr;
  vibra::web::shim::GraphicsState state;
  std::vector<vibra::web::shim::GraphicsState> saved;
  std::vector<std::size_t> group_depths;  ///< saved.size() at each cairo_push_group
  std::vector<vibra::web::shim::Subpath> path;
  std::vector<vibra::web::shim::PathText> path_text;
  bool has_current_point = false;
  vibra::web::shim::DevicePoint current{0, 0};
  cairo_status_t status = CAIRO_STATUS_SUCCESS;
};

namespace vibra::web::shim {

/// The target's operation list, where the context's drawing goes.
inline DrawCommands& commands(cairo_t* cr) { return cr->target->commands; }
/// The user matrix applied to a point, and its inverse.
DevicePoint to_device(const cairo_t* cr, double x, double y);
DevicePoint to_user(const cairo_t* cr, double x, double y);

}  // namespace vibra::web::shim
