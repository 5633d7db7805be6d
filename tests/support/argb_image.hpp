// Test helper: a Cairo ARGB32 image read as native-endian pixel words.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

namespace vibra::test {

/// A Cairo ARGB32 image held as native-endian words, rows `stride` bytes
/// apart (padded rows test that a reader honours the stride).
struct ArgbImage {
  int width, height, stride;
  std::vector<std::uint32_t> words;
  ArgbImage(int w, int h, int padding_words = 0, std::uint32_t fill = 0)
      : width(w), height(h), stride(4 * (w + padding_words)), words(std::size_t(w + padding_words) * h, fill) {}
  std::uint32_t& at(int x, int y) { return words[std::size_t(y) * (stride / 4) + x]; }
  std::uint32_t at(int x, int y) const { return words[std::size_t(y) * (stride / 4) + x]; }
  const std::uint8_t* bytes() const { return reinterpret_cast<const std::uint8_t*>(words.data()); }
};

}  // namespace vibra::test
