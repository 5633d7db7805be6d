// Comparing PNG files by their pixels.
#pragma once
#include <cairo.h>

#include <algorithm>
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

/// Calls `f(x, y)` for each pixel of a PNG within `tolerance` (of 255, per
/// channel) of colour c, in the rows [y0, y1) (all rows when y1 < 0); false
/// when the file cannot be read.
template <class F>
bool for_each_colour_pixel(const std::string& png, const render::Color& c, F&& f, int y0 = 0, int y1 = -1,
                           int tolerance = 30) {
  std::unique_ptr<cairo_surface_t, void (*)(cairo_surface_t*)> s(cairo_image_surface_create_from_png(png.c_str()),
                                                                   cairo_surface_destroy);
  if (cairo_surface_status(s.get()) != CAIRO_STATUS_SUCCESS) return false;
  const unsigned char* data = cairo_image_surface_get_data(s.get());
  const int stride = cairo_image_surface_get_stride(s.get()), width = cairo_image_surface_get_width(s.get());
  const int end = y1 < 0 ? cairo_image_surface_get_height(s.get()) : y1;
  for (int y = y0; y < end; ++y)
    for (int x = 0; x < width; ++x) {
      const unsigned char* p = data + y * stride + 4 * x;  // B, G, R, A
      if (std::abs(p[2] - c.r * 255) < tolerance && std::abs(p[1] - c.g * 255) < tolerance &&
          std::abs(p[0] - c.b * 255) < tolerance)
        f(x, y);
    }
  return true;
}

/// Pixels of a PNG near colour c, in the rows [y0, y1) (all when y1 < 0); -1 when the file cannot be read.
inline int colour_pixels(const std::string& png, const render::Color& c, int y0 = 0, int y1 = -1, int tolerance = 30) {
  int n = 0;
  return for_each_colour_pixel(png, c, [&](int, int) { ++n; }, y0, y1, tolerance) ? n : -1;
}

/// The width over the height of the box around a PNG's pixels near colour c
/// (0 when there are none, or the file cannot be read).
inline double colour_aspect(const std::string& png, const render::Color& c) {
  int x0 = 1 << 30, x1 = -1, y0 = 1 << 30, y1 = -1;
  for_each_colour_pixel(png, c, [&](int x, int y) {
    x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
  });
  return x1 > x0 && y1 > y0 ? double(x1 - x0) / (y1 - y0) : 0;
}

}  // namespace vibra::test
