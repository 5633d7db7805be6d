// A fast zlib stream for PNG scanlines of drawn frames, whose bytes mostly repeat the pixel to the left or the row above.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

namespace vibra::render {

/// Where a scanline compressor keeps its work between frames, so that a
/// reused one allocates nothing.
struct DeflateScratch {
  std::vector<std::uint32_t> tokens;  // literals and (length, distance) matches, in order
};

/// Compresses `size` bytes of PNG scanlines (rows of `row_bytes` bytes, the
/// filter byte first, `pixel_bytes` bytes a pixel) into one zlib stream,
/// written from `out`'s start; returns its length. `out` only grows.
///
/// Why not a general compressor: a drawn frame is long runs of one colour and
/// rows that repeat the row above, so matches are looked for only one pixel
/// back and one row up, which costs a compare per byte instead of a hash
/// search. One dynamic-Huffman block codes the result (stored blocks when
/// that would be larger): on the chapter's diagrams and panels at 720p and
/// 1080p, 4-7x faster than libdeflate at level 6, at files 19-29% larger.
std::size_t deflate_scanlines(const std::uint8_t* data, std::size_t size, std::size_t row_bytes, int pixel_bytes,
                              DeflateScratch& scratch, std::vector<std::uint8_t>& out);

}  // namespace vibra::render
