// Encodes one frame as PNG: scanlines packed as RGB or RGBA and compressed by deflate_scanlines.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

namespace vibra::render {

/// An image as PNG scanlines, ready to compress: each row is a filter byte
/// (None) and then RGB when every pixel is opaque (smaller), else straight
/// RGBA. Reused from frame to frame, so its storage is allocated once.
struct PngScanlines {
  int width = 0, height = 0;
  bool opaque = true;
  std::vector<std::uint8_t> bytes;
};

/// Packs Cairo ARGB32 pixels (premultiplied, native endian; rows `stride`
/// bytes apart) into `out`, reusing its storage.
void pack_png_scanlines(const std::uint8_t* bgra, int width, int height, int stride, PngScanlines& out);

/// Compresses scanlines into a complete PNG file held in the first bytes of
/// `png`, and returns its length. `png` only ever grows, so a buffer reused
/// for every frame costs no allocation and no clearing. Filter None and
/// deflate_scanlines: a drawn frame's bytes repeat the pixel to the left or the
/// row above, which that compressor finds without searching.
std::size_t encode_png(const PngScanlines& scanlines, std::vector<std::uint8_t>& png);

/// Both steps at once, for a single image.
std::vector<std::uint8_t> encode_png(const std::uint8_t* bgra, int width, int height, int stride);

}  // namespace vibra::render
