#pragma once
#include <cstdint>
#include <vector>

namespace vibra::render {

/// Encodes Cairo ARGB32 pixels (premultiplied, native endian) as PNG: RGB when
/// every pixel is opaque (smaller), else straight RGBA; filter None and zlib
/// level 1, which for line art is about 5x faster than Cairo's own writer
/// (level 6 with adaptive filters) at a modestly larger file.
std::vector<std::uint8_t> encode_png(const std::uint8_t* bgra, int width, int height, int stride);

}  // namespace vibra::render
