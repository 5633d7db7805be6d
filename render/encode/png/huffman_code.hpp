// Length-limited canonical Huffman codes from symbol counts, in deflate's form (RFC 1951, 3.2.2).
#pragma once
#include <cstdint>
#include <vector>

namespace vibra::render {

/// A prefix code: each symbol's length in bits (0: unused) and its code with
/// the bits reversed, ready to send least significant bit first as deflate does.
struct HuffmanCode {
  std::vector<std::uint8_t> lengths;
  std::vector<std::uint16_t> codes;
};

/// The optimal code for `counts` whose lengths are at most `max_length`
/// (Huffman's lengths, the longest folded into `max_length` and the Kraft sum
/// restored by lengthening the shortest codes that can give way). Symbols with
/// a count of 0 get no code. At least two symbols must be counted: a caller
/// whose data uses one adds a second.
HuffmanCode make_huffman_code(const std::vector<std::uint32_t>& counts, int max_length);

}  // namespace vibra::render
