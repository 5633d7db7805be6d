// Encodes one frame as PNG: scanlines packed as RGB or RGBA and compressed by deflate_scanlines.
#include "render/encode/png/png_encoder.hpp"

#include <libdeflate.h>

#include <cstring>
#if defined(__x86_64__)
#include <immintrin.h>
#endif
#include <memory>
#include <stdexcept>

#include "render/encode/png/png_deflate.hpp"

namespace vibra::render {

namespace {
std::uint8_t* put32(std::uint8_t* out, std::uint32_t v) {
  for (int shift = 24; shift >= 0; shift -= 8) *out++ = static_cast<std::uint8_t>(v >> shift);
  return out;
}

/// Writes length and type at `out`; the chunk's data must follow them.
/// Returns the end of the data after appending its CRC.
std::uint8_t* finish_chunk(std::uint8_t* out, const char type[4], std::size_t size) {
  put32(out, static_cast<std::uint32_t>(size));
  std::memcpy(out + 4, type, 4);
  return put32(out + 8 + size, static_cast<std::uint32_t>(libdeflate_crc32(0, out + 4, size + 4)));
}

constexpr std::size_t kChunkOverhead = 12;  // length, type, CRC
constexpr std::uint8_t kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};

/// Opaque rows: B, G, R, A bytes to R, G, B. Returns false at the first pixel
/// that is not opaque. Byte loads and stores keep it endian-exact and let the
/// compiler unroll it.
bool pack_opaque_row(const std::uint8_t* in, int width, std::uint8_t* out) {
  std::uint8_t alpha = 0xff;
  for (int x = 0; x < width; ++x, in += 4, out += 3) {
    out[0] = in[2], out[1] = in[1], out[2] = in[0];
    alpha &= in[3];
  }
  return alpha == 0xff;
}

#if defined(__x86_64__)
/// The same with SSSE3's byte shuffle, four pixels at a time: a quarter of a
/// PNG frame's time was this loop. Each 16-byte store writes 4 bytes past the
/// 12 it means, so the last pixels go through the plain loop.
[[gnu::target("ssse3")]] bool pack_opaque_row_ssse3(const std::uint8_t* in, int width, std::uint8_t* out) {
  const __m128i to_rgb = _mm_setr_epi8(2, 1, 0, 6, 5, 4, 10, 9, 8, 14, 13, 12, -1, -1, -1, -1);
  __m128i alpha = _mm_set1_epi8(-1);
  int x = 0;
  for (; x + 6 <= width; x += 4) {
    const __m128i pixels = _mm_loadu_si128(reinterpret_cast<const __m128i*>(in + 4 * std::size_t(x)));
    alpha = _mm_and_si128(alpha, pixels);
    _mm_storeu_si128(reinterpret_cast<__m128i*>(out + 3 * std::size_t(x)), _mm_shuffle_epi8(pixels, to_rgb));
  }
  const bool opaque = (_mm_movemask_epi8(_mm_cmpeq_epi8(alpha, _mm_set1_epi8(-1))) & 0x8888) == 0x8888;
  return pack_opaque_row(in + 4 * std::size_t(x), width - x, out + 3 * std::size_t(x)) && opaque;
}

#endif

using PackRow = bool (*)(const std::uint8_t*, int, std::uint8_t*);

PackRow fastest_pack_opaque_row() {
#if defined(__x86_64__)
  __builtin_cpu_init();
  if (__builtin_cpu_supports("ssse3")) return pack_opaque_row_ssse3;
#endif
  return pack_opaque_row;
}

void pack_rgba_row(const std::uint8_t* bgra, int width, std::uint8_t* out) {
  const auto* in = reinterpret_cast<const std::uint32_t*>(bgra);
  for (int x = 0; x < width; ++x) {
    const std::uint32_t p = in[x];
    std::uint32_t a = p >> 24, r = (p >> 16) & 0xff, g = (p >> 8) & 0xff, b = p & 0xff;
    if (a != 0 && a != 255) {  // Cairo premultiplies; PNG stores straight alpha
      r = (r * 255 + a / 2) / a, g = (g * 255 + a / 2) / a, b = (b * 255 + a / 2) / a;
    }
    *out++ = static_cast<std::uint8_t>(r);
    *out++ = static_cast<std::uint8_t>(g);
    *out++ = static_cast<std::uint8_t>(b);
    *out++ = static_cast<std::uint8_t>(a);
  }
}
}  // namespace

void pack_png_scanlines(const std::uint8_t* bgra, int width, int height, int stride, PngScanlines& out) {
  static const PackRow pack_opaque = fastest_pack_opaque_row();
  out.width = width, out.height = height, out.opaque = true;
  // Assume opaque (every frame vibra draws is) and repack as RGBA if not.
  out.bytes.resize((std::size_t(width) * 3 + 1) * height);
  for (int y = 0; y < height && out.opaque; ++y) {
    std::uint8_t* row = out.bytes.data() + (std::size_t(width) * 3 + 1) * y;
    row[0] = 0;  // filter type None
    out.opaque = pack_opaque(bgra + std::size_t(y) * stride, width, row + 1);
  }
  if (out.opaque) return;
  out.bytes.resize((std::size_t(width) * 4 + 1) * height);
  for (int y = 0; y < height; ++y) {
    std::uint8_t* row = out.bytes.data() + (std::size_t(width) * 4 + 1) * y;
    row[0] = 0;
    pack_rgba_row(bgra + std::size_t(y) * stride, width, row + 1);
  }
}

std::size_t encode_png(const PngScanlines& scanlines, std::vector<std::uint8_t>& png) {
  // One per thread: a worker compresses frame after frame into the same storage.
  thread_local DeflateScratch scratch;
  thread_local std::vector<std::uint8_t> stream;
  const int pixel_bytes = scanlines.opaque ? 3 : 4;
  const std::size_t compressed = deflate_scanlines(scanlines.bytes.data(), scanlines.bytes.size(),
                                                   std::size_t(scanlines.width) * pixel_bytes + 1, pixel_bytes, scratch, stream);
  const std::size_t header_size = sizeof kSignature + kChunkOverhead + 13;
  const std::size_t largest = header_size + kChunkOverhead + compressed + kChunkOverhead;
  if (png.size() < largest) png.resize(largest);

  std::uint8_t* out = png.data();
  std::memcpy(out, kSignature, sizeof kSignature);
  out += sizeof kSignature;
  std::uint8_t* header = out + 8;
  header = put32(header, static_cast<std::uint32_t>(scanlines.width));
  header = put32(header, static_cast<std::uint32_t>(scanlines.height));
  const std::uint8_t rest[5] = {8, static_cast<std::uint8_t>(scanlines.opaque ? 2 : 6), 0, 0, 0};  // 8-bit RGB/RGBA
  std::memcpy(header, rest, sizeof rest);
  out = finish_chunk(out, "IHDR", 13);

  std::memcpy(out + 8, stream.data(), compressed);
  out = finish_chunk(out, "IDAT", compressed);
  out = finish_chunk(out, "IEND", 0);
  return static_cast<std::size_t>(out - png.data());
}

std::vector<std::uint8_t> encode_png(const std::uint8_t* bgra, int width, int height, int stride) {
  PngScanlines scanlines;
  pack_png_scanlines(bgra, width, height, stride, scanlines);
  std::vector<std::uint8_t> png;
  png.resize(encode_png(scanlines, png));
  return png;
}

}  // namespace vibra::render
