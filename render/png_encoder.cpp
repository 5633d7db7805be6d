#include "render/png_encoder.hpp"

#include <zlib.h>

#include <cstring>
#include <stdexcept>

namespace vibra::render {

namespace {
void put32(std::vector<std::uint8_t>& out, std::uint32_t v) {
  for (int shift = 24; shift >= 0; shift -= 8) out.push_back(static_cast<std::uint8_t>(v >> shift));
}

void chunk(std::vector<std::uint8_t>& out, const char type[4], const std::uint8_t* data, size_t size) {
  put32(out, static_cast<std::uint32_t>(size));
  const size_t start = out.size();
  out.insert(out.end(), type, type + 4);
  out.insert(out.end(), data, data + size);
  put32(out, static_cast<std::uint32_t>(crc32(0, out.data() + start, static_cast<uInt>(size + 4))));
}

bool all_opaque(const std::uint8_t* bgra, int width, int height, int stride) {
  for (int y = 0; y < height; ++y) {
    const std::uint32_t* row = reinterpret_cast<const std::uint32_t*>(bgra + size_t(y) * stride);
    for (int x = 0; x < width; ++x)
      if ((row[x] >> 24) != 0xff) return false;
  }
  return true;
}
}  // namespace

std::vector<std::uint8_t> encode_png(const std::uint8_t* bgra, int width, int height, int stride) {
  const bool opaque = all_opaque(bgra, width, height, stride);
  const int channels = opaque ? 3 : 4;
  const size_t row_bytes = size_t(width) * channels + 1;  // filter byte + pixels
  std::vector<std::uint8_t> raw(row_bytes * height);
  for (int y = 0; y < height; ++y) {
    const std::uint32_t* in = reinterpret_cast<const std::uint32_t*>(bgra + size_t(y) * stride);
    std::uint8_t* out = raw.data() + row_bytes * y;
    *out++ = 0;  // filter type None
    for (int x = 0; x < width; ++x) {
      const std::uint32_t p = in[x];
      std::uint32_t a = p >> 24, r = (p >> 16) & 0xff, g = (p >> 8) & 0xff, b = p & 0xff;
      if (!opaque && a != 0 && a != 255) {  // Cairo premultiplies; PNG stores straight alpha
        r = (r * 255 + a / 2) / a, g = (g * 255 + a / 2) / a, b = (b * 255 + a / 2) / a;
      }
      *out++ = static_cast<std::uint8_t>(r);
      *out++ = static_cast<std::uint8_t>(g);
      *out++ = static_cast<std::uint8_t>(b);
      if (!opaque) *out++ = static_cast<std::uint8_t>(a);
    }
  }
  uLongf compressed_size = compressBound(static_cast<uLong>(raw.size()));
  std::vector<std::uint8_t> compressed(compressed_size);
  if (compress2(compressed.data(), &compressed_size, raw.data(), static_cast<uLong>(raw.size()), 1) != Z_OK)
    throw std::runtime_error("zlib failed to compress a frame");

  std::vector<std::uint8_t> png = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  std::vector<std::uint8_t> header;
  put32(header, static_cast<std::uint32_t>(width));
  put32(header, static_cast<std::uint32_t>(height));
  header.insert(header.end(), {8, static_cast<std::uint8_t>(opaque ? 2 : 6), 0, 0, 0});  // 8-bit RGB / RGBA
  chunk(png, "IHDR", header.data(), header.size());
  chunk(png, "IDAT", compressed.data(), compressed_size);
  chunk(png, "IEND", nullptr, 0);
  return png;
}

}  // namespace vibra::render
