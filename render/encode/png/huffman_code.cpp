// Length-limited canonical Huffman codes from symbol counts, in deflate's form (RFC 1951, 3.2.2).
#include "render/encode/png/huffman_code.hpp"

#include <algorithm>
#include <stdexcept>

namespace vibra::render {

namespace {
/// Tree depths of Huffman's code for the counts of `sorted` (ascending): the
/// two-queue construction, leaves and merged nodes each taken in order.
std::vector<int> huffman_depths(const std::vector<int>& sorted, const std::vector<std::uint32_t>& counts) {
  const int n = static_cast<int>(sorted.size());
  std::vector<std::uint64_t> weight(2 * n - 1);
  std::vector<int> parent(2 * n - 1, 0);
  for (int i = 0; i < n; ++i) weight[i] = counts[sorted[i]];
  int leaf = 0, merged = n;
  for (int next = n; next < 2 * n - 1; ++next) {
    auto take = [&] { return leaf < n && (merged >= next || weight[leaf] <= weight[merged]) ? leaf++ : merged++; };
    const int a = take(), b = take();
    weight[next] = weight[a] + weight[b];
    parent[a] = parent[b] = next;
  }
  std::vector<int> depth(2 * n - 1, 0);
  for (int i = 2 * n - 3; i >= 0; --i) depth[i] = depth[parent[i]] + 1;  // parents come after their children
  depth.resize(n);
  return depth;
}

/// How many codes each length has once no length exceeds `max_length`: the
/// deeper codes folded into it, then shortest codes lengthened (one code at
/// length i becomes two at i + 1, and one at max_length goes) until the
/// lengths again fill the code space exactly.
std::vector<int> codes_per_length(const std::vector<int>& depths, int max_length) {
  std::vector<int> per_length(max_length + 1, 0);
  for (int d : depths) ++per_length[std::min(d, max_length)];
  std::uint64_t space = 0;
  for (int len = 1; len <= max_length; ++len) space += std::uint64_t(per_length[len]) << (max_length - len);
  for (; space > (std::uint64_t(1) << max_length); --space) {
    --per_length[max_length];
    for (int len = max_length - 1; len > 0; --len) {
      if (per_length[len] == 0) continue;
      --per_length[len];
      per_length[len + 1] += 2;
      break;
    }
  }
  return per_length;
}

std::uint16_t reversed(std::uint32_t code, int length) {
  std::uint32_t out = 0;
  for (int i = 0; i < length; ++i, code >>= 1) out = (out << 1) | (code & 1);
  return static_cast<std::uint16_t>(out);
}
}  // namespace

HuffmanCode make_huffman_code(const std::vector<std::uint32_t>& counts, int max_length) {
  std::vector<int> used;
  for (int s = 0; s < static_cast<int>(counts.size()); ++s)
    if (counts[s] != 0) used.push_back(s);
  if (used.size() < 2) throw std::logic_error("make_huffman_code needs at least two counted symbols");
  if ((std::size_t(1) << max_length) < used.size()) throw std::logic_error("make_huffman_code: too many symbols for the length");
  std::stable_sort(used.begin(), used.end(), [&](int a, int b) { return counts[a] < counts[b]; });

  // The rarest symbols take the longest codes.
  const std::vector<int> per_length = codes_per_length(huffman_depths(used, counts), max_length);
  HuffmanCode code{std::vector<std::uint8_t>(counts.size(), 0), std::vector<std::uint16_t>(counts.size(), 0)};
  std::size_t next_symbol = 0;
  for (int len = max_length; len > 0; --len)
    for (int k = 0; k < per_length[len]; ++k) code.lengths[used[next_symbol++]] = static_cast<std::uint8_t>(len);

  // Canonical codes: by length, then by symbol.
  std::vector<std::uint32_t> next_code(max_length + 2, 0);
  for (int len = 1; len <= max_length; ++len) next_code[len + 1] = (next_code[len] + per_length[len]) << 1;
  for (std::size_t s = 0; s < counts.size(); ++s)
    if (const int len = code.lengths[s]) code.codes[s] = reversed(next_code[len]++, len);
  return code;
}

}  // namespace vibra::render
