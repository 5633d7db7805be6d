// A fast zlib stream for PNG scanlines of drawn frames, whose bytes mostly repeat the pixel to the left or the row above.
#include "render/encode/png/png_deflate.hpp"

#include <libdeflate.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cstring>

#include "render/encode/png/huffman_code.hpp"

namespace vibra::render {

namespace {
constexpr std::size_t kBlockInput = std::size_t(1) << 20;  // bytes a block codes: its own Huffman code, bounded tokens
constexpr std::size_t kWindow = 32768;                    // deflate's farthest match
constexpr std::size_t kLongestMatch = 258, kShortestMatch = 3;
constexpr std::size_t kStoredMost = 65535;  // bytes in one stored block
constexpr std::uint32_t kMatchFlag = 0x80000000u;
constexpr int kHashBits = 14;  // where four bytes were last seen: 16K positions, 64 KiB
constexpr int kEndOfBlock = 256, kLiteralLengthSymbols = 286, kDistanceSymbols = 30, kCodeLengthSymbols = 19;

// RFC 1951, 3.2.5: the first length and distance of each symbol, and its extra bits.
constexpr std::array<std::uint16_t, 29> kLengthBase = {3,  4,  5,  6,  7,  8,  9,  10, 11,  13,  15,  17,  19,  23, 27,
                                                       31, 35, 43, 51, 59, 67, 83, 99, 115, 131, 163, 195, 227, 258};
constexpr std::array<std::uint8_t, 29> kLengthExtra = {0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2,
                                                       2, 3, 3, 3, 3, 4, 4, 4, 4, 5, 5, 5, 5, 0};
constexpr std::array<std::uint16_t, 30> kDistanceBase = {1,    2,    3,    4,    5,    7,     9,     13,    17,  25,
                                                         33,   49,   65,   97,   129,  193,   257,   385,   513, 769,
                                                         1025, 1537, 2049, 3073, 4097, 6145, 8193, 12289, 16385, 24577};
constexpr std::array<std::uint8_t, 30> kDistanceExtra = {0, 0, 0, 0, 1, 1, 2, 2,  3,  3,  4,  4,  5,  5,  6,
                                                         6, 7, 7, 8, 8, 9, 9, 10, 10, 11, 11, 12, 12, 13, 13};
// The order code-length code lengths are sent in (3.2.7).
constexpr std::array<std::uint8_t, 19> kCodeLengthOrder = {16, 17, 18, 0, 8, 7, 9, 6, 10, 5, 11, 4, 12, 3, 13, 2, 14, 1, 15};

/// Index of the last base at or below `value`.
template <std::size_t N>
int symbol_of(const std::array<std::uint16_t, N>& base, std::size_t value) {
  return static_cast<int>(std::upper_bound(base.begin(), base.end(), value) - base.begin()) - 1;
}

/// How many bytes from `at` (at most `limit`) equal those `distance` before them.
std::size_t repeat_length(const std::uint8_t* data, std::size_t at, std::size_t distance, std::size_t limit) {
  std::size_t n = 0;
  if constexpr (std::endian::native == std::endian::little) {
    for (; n + 8 <= limit; n += 8) {
      std::uint64_t a, b;
      std::memcpy(&a, data + at + n, 8);
      std::memcpy(&b, data + at + n - distance, 8);
      if (a != b) return n + static_cast<std::size_t>(std::countr_zero(a ^ b) >> 3);
    }
  }
  while (n < limit && data[at + n] == data[at + n - distance]) ++n;
  return n;
}

/// Symbol counts of a block and the extra bits its matches carry.
struct BlockCounts {
  std::vector<std::uint32_t> literal_length = std::vector<std::uint32_t>(kLiteralLengthSymbols, 0);
  std::vector<std::uint32_t> distance = std::vector<std::uint32_t>(kDistanceSymbols, 0);
  std::uint64_t extra_bits = 0;
};

/// Tokens for data[begin, end): the longer of the repeats one pixel back and
/// one row up, when it is at least deflate's shortest match; else a literal.
void tokenize(const std::uint8_t* data, std::size_t begin, std::size_t end, std::size_t row_bytes, std::size_t pixel_bytes,
              std::vector<std::uint32_t>& tokens, std::vector<std::uint32_t>& last_seen, BlockCounts& counts) {
  tokens.clear();
  const bool up_reaches = row_bytes <= kWindow;
  for (std::size_t at = begin; at < end;) {
    const std::size_t limit = std::min(kLongestMatch, end - at);
    std::size_t length = 0, distance = 0;
    if (at >= pixel_bytes) length = repeat_length(data, at, pixel_bytes, limit), distance = pixel_bytes;
    // The row above, straight or one pixel to either side (a slanted edge).
    if (up_reaches)
      for (const std::size_t d : {row_bytes, row_bytes + pixel_bytes, row_bytes - pixel_bytes}) {
        if (length >= limit) break;
        if (at < d || d > kWindow) continue;
        if (const std::size_t up = repeat_length(data, at, d, limit); up > length) length = up, distance = d;
      }
    // Where none of those repeat, the last place these four bytes were seen
    // (a glyph, a tick, a hatch drawn again elsewhere), by a hash of them.
    if (length < kShortestMatch + 1 && at + 4 <= end) {
      std::uint32_t key;
      std::memcpy(&key, data + at, 4);
      std::uint32_t& seen = last_seen[(key * 2654435761u) >> (32 - kHashBits)];
      if (seen != 0 && at + 1 - seen <= kWindow)
        if (const std::size_t again = repeat_length(data, at, at + 1 - seen, limit); again > length)
          length = again, distance = at + 1 - seen;
      seen = static_cast<std::uint32_t>(at + 1);
    }
    if (length < kShortestMatch) {
      tokens.push_back(data[at]);
      ++counts.literal_length[data[at++]];
      continue;
    }
    const int length_symbol = symbol_of(kLengthBase, length), distance_symbol = symbol_of(kDistanceBase, distance);
    ++counts.literal_length[257 + length_symbol];
    ++counts.distance[distance_symbol];
    counts.extra_bits += kLengthExtra[length_symbol] + kDistanceExtra[distance_symbol];
    tokens.push_back(kMatchFlag | std::uint32_t(length) << 16 | std::uint32_t(distance));
    at += length;
  }
  ++counts.literal_length[kEndOfBlock];
}

/// Bits sent least significant first, as deflate packs them.
class BitWriter {
 public:
  explicit BitWriter(std::uint8_t* out) : out_(out) {}
  void put(std::uint32_t value, int bits) {
    pending_ |= std::uint64_t(value) << count_;
    count_ += bits;
    if (count_ >= 32) {
      for (int i = 0; i < 4; ++i) *out_++ = static_cast<std::uint8_t>(pending_ >> (8 * i));
      pending_ >>= 32;
      count_ -= 32;
    }
  }
  /// Pads to a whole byte and returns where the next byte goes.
  std::uint8_t* align() {
    for (; count_ > 0; count_ -= 8, pending_ >>= 8) *out_++ = static_cast<std::uint8_t>(pending_);
    count_ = 0, pending_ = 0;
    return out_;
  }
  void skip_to(std::uint8_t* out) { out_ = out; }

 private:
  std::uint8_t* out_;
  std::uint64_t pending_ = 0;
  int count_ = 0;
};

/// The code-length symbols (with their extra bits) that send `lengths`: runs
/// of zeros as 17 and 18, repeats of a length as 16.
std::vector<std::pair<int, int>> code_length_symbols(const std::vector<std::uint8_t>& lengths) {
  std::vector<std::pair<int, int>> out;
  for (std::size_t i = 0; i < lengths.size();) {
    const int len = lengths[i];
    std::size_t run = 1;
    while (i + run < lengths.size() && lengths[i + run] == len) ++run;
    i += run;
    if (len == 0) {
      for (; run >= 11; run -= std::min<std::size_t>(run, 138)) out.push_back({18, int(std::min<std::size_t>(run, 138) - 11)});
      if (run >= 3) out.push_back({17, int(run - 3)}), run = 0;
    } else {
      out.push_back({len, 0}), --run;
      for (; run >= 3; run -= std::min<std::size_t>(run, 6)) out.push_back({16, int(std::min<std::size_t>(run, 6) - 3)});
    }
    for (; run > 0; --run) out.push_back({len, 0});
  }
  return out;
}

constexpr int extra_bits_of_code_length_symbol(int symbol) { return symbol == 16 ? 2 : symbol == 17 ? 3 : symbol == 18 ? 7 : 0; }

/// Counts with at least two symbols, as a Huffman code needs (an unused
/// symbol gets a count of 1 and costs nothing: it is never sent).
std::vector<std::uint32_t> with_two_symbols(std::vector<std::uint32_t> counts) {
  for (std::size_t s = 0; std::count_if(counts.begin(), counts.end(), [](std::uint32_t c) { return c != 0; }) < 2; ++s)
    if (counts[s] == 0) counts[s] = 1;
  return counts;
}

/// A block's dynamic Huffman codes and the header that sends them.
struct BlockCode {
  HuffmanCode literal_length, distance, code_length;
  std::vector<std::pair<int, int>> header_symbols;
  int literal_codes = 257, distance_codes = 1, code_length_codes = 4;
  std::uint64_t bits = 0;  // the whole block
};

std::size_t used_prefix(const std::vector<std::uint8_t>& lengths, std::size_t at_least) {
  std::size_t n = lengths.size();
  while (n > at_least && lengths[n - 1] == 0) --n;
  return n;
}

BlockCode plan_block(const BlockCounts& counts) {
  BlockCode code;
  code.literal_length = make_huffman_code(with_two_symbols(counts.literal_length), 15);
  code.distance = make_huffman_code(with_two_symbols(counts.distance), 15);
  code.literal_codes = static_cast<int>(used_prefix(code.literal_length.lengths, 257));
  code.distance_codes = static_cast<int>(used_prefix(code.distance.lengths, 1));
  std::vector<std::uint8_t> lengths(code.literal_length.lengths.begin(), code.literal_length.lengths.begin() + code.literal_codes);
  lengths.insert(lengths.end(), code.distance.lengths.begin(), code.distance.lengths.begin() + code.distance_codes);
  code.header_symbols = code_length_symbols(lengths);
  std::vector<std::uint32_t> header_counts(kCodeLengthSymbols, 0);
  for (const auto& [symbol, extra] : code.header_symbols) ++header_counts[symbol];
  code.code_length = make_huffman_code(with_two_symbols(header_counts), 7);
  for (int i = kCodeLengthSymbols; i > 4; --i)
    if (code.code_length.lengths[kCodeLengthOrder[i - 1]] != 0) { code.code_length_codes = i; break; }

  code.bits = 3 + 5 + 5 + 4 + 3 * code.code_length_codes + counts.extra_bits;
  for (const auto& [symbol, extra] : code.header_symbols)
    code.bits += code.code_length.lengths[symbol] + extra_bits_of_code_length_symbol(symbol);
  for (int s = 0; s < kLiteralLengthSymbols; ++s) code.bits += std::uint64_t(counts.literal_length[s]) * code.literal_length.lengths[s];
  for (int s = 0; s < kDistanceSymbols; ++s) code.bits += std::uint64_t(counts.distance[s]) * code.distance.lengths[s];
  return code;
}

void write_huffman_block(BitWriter& bits, const BlockCode& code, const std::vector<std::uint32_t>& tokens, bool last) {
  bits.put(last ? 1 : 0, 1);
  bits.put(2, 2);  // dynamic Huffman codes
  bits.put(code.literal_codes - 257, 5);
  bits.put(code.distance_codes - 1, 5);
  bits.put(code.code_length_codes - 4, 4);
  for (int i = 0; i < code.code_length_codes; ++i) bits.put(code.code_length.lengths[kCodeLengthOrder[i]], 3);
  for (const auto& [symbol, extra] : code.header_symbols) {
    bits.put(code.code_length.codes[symbol], code.code_length.lengths[symbol]);
    if (const int n = extra_bits_of_code_length_symbol(symbol)) bits.put(extra, n);
  }
  const HuffmanCode& lit = code.literal_length;
  const HuffmanCode& dist = code.distance;
  for (const std::uint32_t token : tokens) {
    if (!(token & kMatchFlag)) {
      bits.put(lit.codes[token], lit.lengths[token]);
      continue;
    }
    const std::size_t length = (token >> 16) & 0x1ff, distance = token & 0xffff;
    const int ls = symbol_of(kLengthBase, length), ds = symbol_of(kDistanceBase, distance);
    bits.put(lit.codes[257 + ls], lit.lengths[257 + ls]);
    bits.put(static_cast<std::uint32_t>(length - kLengthBase[ls]), kLengthExtra[ls]);
    bits.put(dist.codes[ds], dist.lengths[ds]);
    bits.put(static_cast<std::uint32_t>(distance - kDistanceBase[ds]), kDistanceExtra[ds]);
  }
  bits.put(lit.codes[kEndOfBlock], lit.lengths[kEndOfBlock]);
}

/// data[begin, end) as stored blocks: for data a Huffman code cannot shrink.
void write_stored_blocks(BitWriter& bits, const std::uint8_t* data, std::size_t begin, std::size_t end, bool last) {
  do {
    const std::size_t n = std::min(kStoredMost, end - begin);
    const bool final_block = last && begin + n == end;
    bits.put(final_block ? 1 : 0, 1);
    bits.put(0, 2);
    std::uint8_t* out = bits.align();
    const std::uint8_t header[4] = {std::uint8_t(n), std::uint8_t(n >> 8), std::uint8_t(~n), std::uint8_t(~n >> 8)};
    std::memcpy(out, header, 4);
    std::memcpy(out + 4, data + begin, n);
    bits.skip_to(out + 4 + n);
    begin += n;
  } while (begin < end);
}

std::size_t stored_bytes(std::size_t n) { return n + 5 * (n / kStoredMost + 1); }
}  // namespace

std::size_t deflate_scanlines(const std::uint8_t* data, std::size_t size, std::size_t row_bytes, int pixel_bytes,
                              DeflateScratch& scratch, std::vector<std::uint8_t>& out) {
  const std::size_t blocks = std::max<std::size_t>(1, (size + kBlockInput - 1) / kBlockInput);
  const std::size_t bound = 2 + stored_bytes(size) + 5 * blocks + 4 + 8;  // zlib header, blocks, Adler-32
  if (out.size() < bound) out.resize(bound);
  out[0] = 0x78, out[1] = 0x01;  // deflate, 32 KiB window, fastest-level hint
  BitWriter bits(out.data() + 2);
  scratch.last_seen.assign(std::size_t(1) << kHashBits, 0);  // positions + 1 of this image; 0: none
  std::size_t begin = 0;
  do {
    const std::size_t end = std::min(size, begin + kBlockInput);
    BlockCounts counts;
    tokenize(data, begin, end, row_bytes, static_cast<std::size_t>(pixel_bytes), scratch.tokens, scratch.last_seen, counts);
    const BlockCode code = plan_block(counts);
    if ((code.bits + 7) / 8 < stored_bytes(end - begin)) write_huffman_block(bits, code, scratch.tokens, end == size);
    else write_stored_blocks(bits, data, begin, end, end == size);
    begin = end;
  } while (begin < size);
  std::uint8_t* tail = bits.align();
  const std::uint32_t adler = libdeflate_adler32(1, data, size);
  for (int shift = 24; shift >= 0; shift -= 8) *tail++ = static_cast<std::uint8_t>(adler >> shift);
  return static_cast<std::size_t>(tail - out.data());
}

}  // namespace vibra::render
