// deflate_scanlines and its Huffman codes: every stream inflates to its input, codes are prefix-free and optimal within their length limit.
#include <catch2/catch.hpp>
#include <libdeflate.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "render/encode/png/huffman_code.hpp"
#include "render/encode/png/png_deflate.hpp"

using vibra::render::DeflateScratch;
using vibra::render::deflate_scanlines;
using vibra::render::make_huffman_code;

namespace {
/// The Kraft sum of a code's lengths, in units of 2^-max_length.
std::uint64_t kraft_units(const std::vector<std::uint8_t>& lengths, int max_length) {
  std::uint64_t units = 0;
  for (int len : lengths)
    if (len) units += std::uint64_t(1) << (max_length - len);
  return units;
}

std::uint16_t bit_reversed(std::uint16_t code, int length) {
  std::uint16_t out = 0;
  for (int i = 0; i < length; ++i, code >>= 1) out = static_cast<std::uint16_t>((out << 1) | (code & 1));
  return out;
}

std::vector<std::uint8_t> inflate(const std::vector<std::uint8_t>& stream, std::size_t size, std::size_t expected_size) {
  std::vector<std::uint8_t> out(expected_size + 1);
  std::size_t actual = 0;
  libdeflate_decompressor* d = libdeflate_alloc_decompressor();
  const libdeflate_result result = libdeflate_zlib_decompress(d, stream.data(), size, out.data(), out.size(), &actual);
  libdeflate_free_decompressor(d);
  REQUIRE(result == LIBDEFLATE_SUCCESS);
  out.resize(actual);
  return out;
}

/// Scanlines of a line drawing: white, a few flat-coloured rectangles, one
/// anti-aliased diagonal, each row led by filter byte 0.
std::vector<std::uint8_t> drawing(int width, int height, int pixel_bytes) {
  const std::size_t row = std::size_t(width) * pixel_bytes + 1;
  std::vector<std::uint8_t> bytes(row * height, 255);
  for (int y = 0; y < height; ++y) {
    std::uint8_t* r = bytes.data() + row * y;
    r[0] = 0;
    for (int x = 0; x < width; ++x) {
      std::uint8_t* p = r + 1 + std::size_t(x) * pixel_bytes;
      if (x > width / 4 && x < width / 2 && y > height / 3 && y < height / 2) p[0] = 40, p[1] = 90, p[2] = 200;
      const double off = std::abs(x - 1.7 * y);
      if (off < 2) p[0] = p[1] = p[2] = static_cast<std::uint8_t>(255 * off / 2);
    }
  }
  return bytes;
}

void check_round_trip(const std::vector<std::uint8_t>& bytes, int width, int pixel_bytes) {
  DeflateScratch scratch;
  std::vector<std::uint8_t> stream;
  const std::size_t n = deflate_scanlines(bytes.data(), bytes.size(), std::size_t(width) * pixel_bytes + 1, pixel_bytes, scratch, stream);
  INFO(bytes.size() << " bytes in rows of " << width << " pixels of " << pixel_bytes << " bytes, " << n << " compressed");
  CHECK(inflate(stream, n, bytes.size()) == bytes);
}
}  // namespace

TEST_CASE("huffman code: the book example's lengths give RFC 1951's canonical codes", "[png][deflate]") {
  // RFC 1951, 3.2.2: A..H with lengths 3,3,3,3,3,2,4,4 have codes 010 011 100 101 110 00 1110 1111.
  // Counts whose optimal lengths are exactly those: F most common, G and H rarest.
  const std::vector<std::uint32_t> counts = {10, 10, 10, 10, 10, 24, 5, 5};
  const auto code = make_huffman_code(counts, 15);
  CHECK(code.lengths == std::vector<std::uint8_t>{3, 3, 3, 3, 3, 2, 4, 4});
  const std::vector<std::uint16_t> msb_first = {0b010, 0b011, 0b100, 0b101, 0b110, 0b00, 0b1110, 0b1111};
  for (std::size_t s = 0; s < counts.size(); ++s) CHECK(bit_reversed(code.codes[s], code.lengths[s]) == msb_first[s]);
}

TEST_CASE("huffman code: Fibonacci counts are cut to the length limit, prefix-free and complete", "[png][deflate]") {
  // Fibonacci counts make the deepest Huffman tree: 30 symbols would need 29 bits.
  std::vector<std::uint32_t> counts = {1, 1};
  while (counts.size() < 30) counts.push_back(counts[counts.size() - 1] + counts[counts.size() - 2]);
  for (int limit : {7, 9, 15}) {
    const auto code = make_huffman_code(counts, limit);
    CHECK(*std::max_element(code.lengths.begin(), code.lengths.end()) == limit);
    CHECK(kraft_units(code.lengths, limit) == (std::uint64_t(1) << limit));  // complete: no code space wasted
    for (std::size_t s = 1; s < counts.size(); ++s) CHECK(code.lengths[s] <= code.lengths[s - 1]);  // commoner, not longer
  }
  // Under a limit that does not bind, the lengths are Huffman's.
  const auto free_code = make_huffman_code({1, 1, 2, 4}, 15);
  CHECK(free_code.lengths == std::vector<std::uint8_t>{3, 3, 2, 1});
}

TEST_CASE("huffman code: unused symbols get no code, and a lone symbol is refused", "[png][deflate]") {
  const auto code = make_huffman_code({0, 7, 0, 3, 0}, 15);
  CHECK(code.lengths == std::vector<std::uint8_t>{0, 1, 0, 1, 0});
  CHECK_THROWS_AS(make_huffman_code({0, 5, 0}, 15), std::logic_error);
}

TEST_CASE("deflate_scanlines: drawings inflate to the same bytes, RGB and RGBA, small and wide", "[png][deflate]") {
  for (int pixel_bytes : {3, 4})
    for (auto [w, h] : {std::pair{1, 1}, {7, 3}, {320, 180}, {1280, 720}, {12000, 4}}) {  // 12000: the row above is out of reach
      check_round_trip(drawing(w, h, pixel_bytes), w, pixel_bytes);
    }
}

TEST_CASE("deflate_scanlines: noise falls back to stored blocks and still inflates", "[png][deflate]") {
  std::mt19937 random(7);
  std::vector<std::uint8_t> noise(3 * 1000 * 1000 + 17);  // three blocks and a bit
  for (auto& b : noise) b = static_cast<std::uint8_t>(random());
  DeflateScratch scratch;
  std::vector<std::uint8_t> stream;
  const std::size_t n = deflate_scanlines(noise.data(), noise.size(), 3001, 3, scratch, stream);
  CHECK(n <= noise.size() + 5 * (noise.size() / 65535 + 8) + 6);  // no worse than stored
  CHECK(inflate(stream, n, noise.size()) == noise);
  CHECK(inflate(stream, deflate_scanlines(noise.data(), 0, 3001, 3, scratch, stream), 0).empty());
}

TEST_CASE("deflate_scanlines: a white 1080p frame compresses like a run, a drawing several times below its size",
          "[png][deflate]") {
  const auto white = drawing(1920, 1080, 3);
  std::vector<std::uint8_t> blank(white.size(), 255);
  for (std::size_t y = 0; y < 1080; ++y) blank[y * (1920 * 3 + 1)] = 0;
  DeflateScratch scratch;
  std::vector<std::uint8_t> stream;
  // 6.2 MB as matches of at most 258 bytes, nearly all of one length and
  // distance: 1-bit codes, so about 2 bits a match and 24,000 matches (6 KB).
  CHECK(deflate_scanlines(blank.data(), blank.size(), 1920 * 3 + 1, 3, scratch, stream) < 8000);
  CHECK(deflate_scanlines(white.data(), white.size(), 1920 * 3 + 1, 3, scratch, stream) < white.size() / 50);
}

TEST_CASE("deflate_scanlines: a glyph drawn again elsewhere in the row costs a fraction of drawing it the first time",
          "[png][deflate]") {
  // A 12x12 patch of noise (no pixel repeats its left or upper neighbour),
  // stamped at x = 40 and again at x = 300 of each row: the second stamp is
  // found by where its bytes were last seen, 260 pixels back.
  const int width = 400, height = 12;
  std::mt19937 random(3);
  std::vector<std::uint8_t> glyph(12 * 12 * 3);
  for (auto& b : glyph) b = static_cast<std::uint8_t>(random());
  auto image = [&](bool twice) {
    std::vector<std::uint8_t> bytes((width * 3 + 1) * height, 255);
    for (int y = 0; y < height; ++y) {
      bytes[std::size_t(y) * (width * 3 + 1)] = 0;
      for (int x0 : twice ? std::vector<int>{40, 300} : std::vector<int>{40})
        std::copy_n(glyph.begin() + y * 36, 36, bytes.begin() + std::size_t(y) * (width * 3 + 1) + 1 + 3 * x0);
    }
    return bytes;
  };
  DeflateScratch scratch;
  std::vector<std::uint8_t> stream;
  const auto once = image(false), twice = image(true);
  const std::size_t one = deflate_scanlines(once.data(), once.size(), width * 3 + 1, 3, scratch, stream);
  const std::size_t two = deflate_scanlines(twice.data(), twice.size(), width * 3 + 1, 3, scratch, stream);
  CHECK(inflate(stream, two, twice.size()) == twice);
  INFO("one glyph: " << one << " bytes, two: " << two);
  CHECK(two < one + (one - 40) / 4);  // the second stamp: a few matches a row, not 432 literals again
}
