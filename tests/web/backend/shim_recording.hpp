// A recording surface of the browser build's Cairo with a context drawing into it, for the backend's tests.
#pragma once
#include <cairo.h>

#include <memory>

namespace vibra::web::test {

struct Recording {
  std::shared_ptr<cairo_surface_t> surface;
  std::shared_ptr<cairo_t> cr;
};

/// A width x height recording surface and a context drawing into it.
inline Recording recording(double width, double height) {
  const cairo_rectangle_t extents{0, 0, width, height};
  std::shared_ptr<cairo_surface_t> s(cairo_recording_surface_create(CAIRO_CONTENT_COLOR_ALPHA, &extents),
                                     cairo_surface_destroy);
  return {s, std::shared_ptr<cairo_t>(cairo_create(s.get()), cairo_destroy)};
}

}  // namespace vibra::web::test
