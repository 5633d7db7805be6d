// Comparing PNG files by their pixels.
#pragma once
#include <cairo.h>

#include <cmath>
#include <memory>
#include <string>

#include "render/draw/color.hpp"

namespace vibra::test {

/// Peak signal-to-noise ratio of two PNG files' colour channels, in dB
/// (infinite when identical); -1 when they cannot be read or differ in size.
inline double psnr(const std::string& a, const std::string& b) {
  cairo_surface_t* x = cairo_image_surface_create_from_png(a.c_str());
  cairo_surface_t* y = cairo_image_surface_create_from_png(b.c_str());
  double result = -1;
  if (cairo_surface_status(x) == CAIRO_STATUS_SUCCESS && cairo_surface_status(y) == CAIRO_STATUS_SUCCESS &&
      cairo_image_surface_get_width(x) == cairo_image_surface_get_width(y) &&
      cairo_image_surface_get_height(x) == cairo_image_surface_get_height(y)) {
    const int w = cairo_image_surface_get_width(x), h = cairo_image_surface_get_height(x);
    double sum = 0;
    for (int r = 0; r < h; ++r) {
      const auto* p = cairo_image_surface_get_data(x) + r * cairo_image_surface_get_stride(x);
      const auto* q = cairo_image_surface_get_data(y) + r * cairo_image_surface_get_stride(y);
      for (int i = 0; i < 4 * w; ++i)
        if (i % 4 != 3) sum += double(p[i] - q[i]) * (p[i] - q[i]);
    }
    const double mse = sum / (3.0 * w * h);
    result = mse == 0 ? INFINITY : 10 * std::log10(255.0 * 255.0 / mse);
  }
  cairo_surface_destroy(x);
  cairo_surface_destroy(y);
  return result;
}

/// Pixels of a PNG within `tolerance` (of 255, per channel) of colour c, in
/// the rows [y0, y1) (all rows when y1 < 0); -1 when the file cannot be read.
inline int colour_pixels(const std::string& png, const render::Color& c, int y0 = 0, int y1 = -1, int tolerance = 30) {
  std::unique_ptr<cairo_surface_t, void (*)(cairo_surface_t*)> s(cairo_image_surface_create_from_png(png.c_str()),
                                                                   cairo_surface_destroy);
  if (cairo_surface_status(s.get()) != CAIRO_STATUS_SUCCESS) return -1;
  const unsigned char* data = cairo_image_surface_get_data(s.get());
  const int stride = cairo_image_surface_get_stride(s.get()), width = cairo_image_surface_get_width(s.get());
  const int end = y1 < 0 ? cairo_image_surface_get_height(s.get()) : y1;
  int n = 0;
  for (int y = y0; y < end; ++y)
    for (int x = 0; x < width; ++x) {
      const unsigned char* p = data + y * stride + 4 * x;
      n += std::abs(p[2] - c.r * 255) < tolerance && std::abs(p[1] - c.g * 255) < tolerance &&
           std::abs(p[0] - c.b * 255) < tolerance;
    }
  return n;
}

}  // namespace vibra::test
