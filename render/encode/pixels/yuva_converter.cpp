// BGRA to YUVA 4:2:0 (BT.709) for videos with an alpha plane (--transparent).
#include "render/encode/pixels/yuva_converter.hpp"

#include <algorithm>
#include <cstring>
#include <stdexcept>

#include "render/encode/pixels/bt709.hpp"

namespace vibra::render {

namespace {
using bt709::kKb;
using bt709::kKg;
using bt709::kKr;

/// Straight (not premultiplied) colour in 0..1 and alpha in 0..1.
struct Straight {
  double r, g, b, a;
};

Straight straight(std::uint32_t p) {
  const double a = (p >> 24) / 255.0;
  if (a <= 0) return {0, 0, 0, 0};
  const double k = 1 / (255.0 * a);
  return {std::min(1.0, (p >> 16 & 0xff) * k), std::min(1.0, (p >> 8 & 0xff) * k), std::min(1.0, (p & 0xff) * k), a};
}

double luma(double r, double g, double b) { return kKr * r + kKg * g + kKb * b; }
double blue_difference(double r, double g, double b) { return (b - luma(r, g, b)) / (2 * (1 - kKb)); }
double red_difference(double r, double g, double b) { return (r - luma(r, g, b)) / (2 * (1 - kKr)); }

/// A value in 0..1 (luma) or -0.5..0.5 (chroma) to `bits` limited range.
int limited_luma(double y, int bits) {
  const int scale = 1 << (bits - 8);
  return std::clamp(int(16 * scale + y * 219 * scale + 0.5), 0, (256 * scale) - 1);
}
int limited_chroma(double c, int bits) {
  const int scale = 1 << (bits - 8);
  return std::clamp(int(128 * scale + c * 224 * scale + (c < 0 ? -0.5 : 0.5)), 0, (256 * scale) - 1);
}

const std::uint32_t* row_of(const std::uint8_t* argb32, int stride, int y) {
  return reinterpret_cast<const std::uint32_t*>(argb32 + std::ptrdiff_t(y) * stride);
}
}  // namespace

YuvaConverter::YuvaConverter(Layout layout, int width, int height) : layout_(layout), width_(width), height_(height) {
  if (width < 1 || height < 1 || width > 8192 || height > 8192)
    throw std::invalid_argument("YuvaConverter: size out of range");
}

void YuvaConverter::convert(const std::uint8_t* argb32, int stride, const YuvaPlanes& out) const {
  if (layout_ == Layout::yuva420p)
    convert_420(argb32, stride, out);
  else
    convert_444_10(argb32, stride, out);
}

void YuvaConverter::convert_420(const std::uint8_t* argb32, int stride, const YuvaPlanes& out) const {
  for (int y = 0; y < height_; ++y) {
    const std::uint32_t* in = row_of(argb32, stride, y);
    std::uint8_t* luma_row = out.data[0] + std::ptrdiff_t(y) * out.linesize[0];
    std::uint8_t* alpha_row = out.data[3] + std::ptrdiff_t(y) * out.linesize[3];
    for (int x = 0; x < width_; ++x) {
      const Straight s = straight(in[x]);
      luma_row[x] = static_cast<std::uint8_t>(limited_luma(luma(s.r, s.g, s.b), 8));
      alpha_row[x] = static_cast<std::uint8_t>(in[x] >> 24);
    }
  }
  for (int cy = 0; cy < (height_ + 1) / 2; ++cy) {
    std::uint8_t* u = out.data[1] + std::ptrdiff_t(cy) * out.linesize[1];
    std::uint8_t* v = out.data[2] + std::ptrdiff_t(cy) * out.linesize[2];
    for (int cx = 0; cx < (width_ + 1) / 2; ++cx) {
      // The block's colour: premultiplied sums over the alpha sum.
      double r = 0, g = 0, b = 0, a = 0;
      for (int y = 2 * cy; y < std::min(2 * cy + 2, height_); ++y)
        for (int x = 2 * cx; x < std::min(2 * cx + 2, width_); ++x) {
          const std::uint32_t p = row_of(argb32, stride, y)[x];
          r += p >> 16 & 0xff, g += p >> 8 & 0xff, b += p & 0xff, a += p >> 24;
        }
      if (a > 0) r = std::min(1.0, r / a), g = std::min(1.0, g / a), b = std::min(1.0, b / a);
      u[cx] = static_cast<std::uint8_t>(limited_chroma(blue_difference(r, g, b), 8));
      v[cx] = static_cast<std::uint8_t>(limited_chroma(red_difference(r, g, b), 8));
    }
  }
}

void YuvaConverter::convert_444_10(const std::uint8_t* argb32, int stride, const YuvaPlanes& out) const {
  for (int y = 0; y < height_; ++y) {
    const std::uint32_t* in = row_of(argb32, stride, y);
    auto plane = [&](int i) { return reinterpret_cast<std::uint16_t*>(out.data[i] + std::ptrdiff_t(y) * out.linesize[i]); };
    std::uint16_t *luma_row = plane(0), *u = plane(1), *v = plane(2), *alpha = plane(3);
    for (int x = 0; x < width_; ++x) {
      const Straight s = straight(in[x]);
      luma_row[x] = static_cast<std::uint16_t>(limited_luma(luma(s.r, s.g, s.b), 10));
      u[x] = static_cast<std::uint16_t>(limited_chroma(blue_difference(s.r, s.g, s.b), 10));
      v[x] = static_cast<std::uint16_t>(limited_chroma(red_difference(s.r, s.g, s.b), 10));
      alpha[x] = static_cast<std::uint16_t>(((in[x] >> 24) * 1023 + 127) / 255);
    }
  }
}

}  // namespace vibra::render
