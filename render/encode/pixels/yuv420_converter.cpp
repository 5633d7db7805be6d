// BGRA to YUV 4:2:0 (BT.709, limited range), converting only the blocks that changed.
#include "render/encode/pixels/yuv420_converter.hpp"

#include <algorithm>
#include <cstring>
#include <stdexcept>

#include "render/encode/pixels/bt709.hpp"

namespace vibra::render {

namespace {
// BT.709 (bt709.hpp) into limited range: Y in 16..235 and
// Cb, Cr in 16..240, as fixed-point weights of 8-bit R, G, B scaled by 2^16.
// Each row of weights is rounded so that it sums exactly to its target
// (219/255 for Y, 0 for Cb and Cr): white is 235 and greys have no colour.
using bt709::kKb;
using bt709::kKr;
constexpr int kShift = 16;
constexpr int fixed(double x) { return static_cast<int>(x * (1 << kShift) + (x < 0 ? -0.5 : 0.5)); }

constexpr double kLuma = 219.0 / 255, kChroma = 224.0 / 255;
constexpr int kYr = fixed(kLuma * kKr), kYb = fixed(kLuma * kKb), kYg = fixed(kLuma) - kYr - kYb;
constexpr int kUb = fixed(kChroma / 2), kUr = fixed(-kChroma / 2 * kKr / (1 - kKb)), kUg = -kUb - kUr;
constexpr int kVr = fixed(kChroma / 2), kVb = fixed(-kChroma / 2 * kKb / (1 - kKr)), kVg = -kVr - kVb;

inline int red(std::uint32_t p) { return static_cast<int>(p >> 16 & 0xff); }
inline int green(std::uint32_t p) { return static_cast<int>(p >> 8 & 0xff); }
inline int blue(std::uint32_t p) { return static_cast<int>(p & 0xff); }

inline std::uint8_t luma(std::uint32_t p) {
  return static_cast<std::uint8_t>((kYr * red(p) + kYg * green(p) + kYb * blue(p) + (16 << kShift) +
                                    (1 << (kShift - 1))) >> kShift);
}
}  // namespace

Yuv420Converter::Yuv420Converter(int width, int height, int out_width, int out_height)
    : width_(width), height_(height), out_width_(out_width), out_height_(out_height),
      padded_width_((width + 1) & ~1), padded_height_((height + 1) & ~1) {
  if (width < 1 || height < 1 || width > 8192 || height > 8192)
    throw std::invalid_argument("Yuv420Converter: size out of range");
  if ((out_width != width && out_width != padded_width_) || (out_height != height && out_height != padded_height_))
    throw std::invalid_argument("Yuv420Converter: the output may only round the size up to even");
  previous_ = HugePageArray<std::uint32_t>(std::size_t(padded_width_) * padded_height_);
  y_ = HugePageArray<std::uint8_t>(std::size_t(padded_width_) * padded_height_);
  u_ = HugePageArray<std::uint8_t>(y_.size() / 4);
  v_ = HugePageArray<std::uint8_t>(y_.size() / 4);
  block_converted_.assign(std::size_t(padded_height_ / 2) * blocks_per_row(), 0);
}

long long Yuv420Converter::blocks() const {
  return (padded_height_ / 2LL) * ((width_ + kBlockWidth - 1) / kBlockWidth);
}

void Yuv420Converter::convert(const std::uint8_t* argb32, int stride, const Yuv420Planes& out, const Damage* changed,
                              std::uint64_t* out_holds) {
  converted_ = 0;
  ++conversion_;
  const int pairs = padded_height_ / 2;
  if (first_ || !changed || changed->all()) {
    spans_.assign(1, {0, width_});
    for (int pair = 0; pair < pairs; ++pair) convert_spans(pair, argb32, stride);
  } else if (!changed->empty()) {
    // The set of rectangles a row pair meets changes only where one starts or
    // ends: work out the columns once per stretch of pairs between those.
    std::vector<int>& edges = edges_;
    edges.clear();
    for (const DamageRect& r : changed->rects()) edges.push_back(r.y0 / 2), edges.push_back((r.y1 + 1) / 2);
    edges.push_back(pairs);
    std::sort(edges.begin(), edges.end());
    int from = 0;
    for (const int to : edges) {
      if (to <= from) continue;
      changed->spans(2 * from, 2 * from + 2, spans_);
      if (!spans_.empty())
        for (int pair = from; pair < std::min(to, pairs); ++pair) convert_spans(pair, argb32, stride);
      from = to;
    }
  }
  first_ = false;
  const std::uint64_t since = out_holds ? *out_holds : 0;
  if (out_holds) *out_holds = conversion_;
  copy_out(out, since);
}

void Yuv420Converter::convert_spans(int pair, const std::uint8_t* argb32, int stride) {
  const auto* top = reinterpret_cast<const std::uint32_t*>(argb32 + std::ptrdiff_t(2 * pair) * stride);
  const int bottom_row = std::min(2 * pair + 1, height_ - 1);  // an odd height repeats the last row
  const auto* bottom = reinterpret_cast<const std::uint32_t*>(argb32 + std::ptrdiff_t(bottom_row) * stride);
  int next_block = 0;  // spans may share a block: visit each once
  for (const auto& [span_x0, span_x1] : spans_)
    for (int block = std::max(next_block, span_x0 / kBlockWidth); block * kBlockWidth < span_x1; ++block) {
      next_block = block + 1;
      convert_if_changed(pair, block * kBlockWidth, top, bottom);
    }
}

void Yuv420Converter::convert_if_changed(int pair, int x0, const std::uint32_t* top, const std::uint32_t* bottom) {
  std::uint32_t* kept_top = previous_.data() + std::size_t(2 * pair) * padded_width_;
  std::uint32_t* kept_bottom = kept_top + padded_width_;
  const int x1 = std::min(x0 + kBlockWidth, width_);
  const std::size_t bytes = std::size_t(x1 - x0) * 4;
  if (!first_ && std::memcmp(top + x0, kept_top + x0, bytes) == 0 &&
      std::memcmp(bottom + x0, kept_bottom + x0, bytes) == 0)
    return;
  std::memcpy(kept_top + x0, top + x0, bytes);
  std::memcpy(kept_bottom + x0, bottom + x0, bytes);
  if (x1 < padded_width_ && x1 == width_) {  // an odd width repeats the last column
    kept_top[x1] = kept_top[x1 - 1];
    kept_bottom[x1] = kept_bottom[x1 - 1];
  }
  convert_block(pair, x0, x1 == width_ ? padded_width_ : x1);
  block_converted_[std::size_t(pair) * blocks_per_row() + x0 / kBlockWidth] = conversion_;
  ++converted_;
}

void Yuv420Converter::copy_out(const Yuv420Planes& out, std::uint64_t since) const {
  const int per_row = blocks_per_row(), chroma_height = (out_height_ + 1) / 2;
  for (int pair = 0; pair < padded_height_ / 2; ++pair) {
    const std::uint64_t* converted = block_converted_.data() + std::size_t(pair) * per_row;
    for (int block = 0; block < per_row;) {
      if (converted[block] <= since) {
        ++block;
        continue;
      }
      int end = block + 1;  // a run of blocks to copy, in one go
      while (end < per_row && converted[end] > since) ++end;
      const int x0 = block * kBlockWidth, x1 = end == per_row ? out_width_ : end * kBlockWidth;
      for (int row = 2 * pair; row < std::min(2 * pair + 2, out_height_); ++row)
        std::memcpy(out.data[0] + std::ptrdiff_t(row) * out.linesize[0] + x0,
                    y_.data() + std::size_t(row) * padded_width_ + x0, x1 - x0);
      if (pair < chroma_height) {
        const std::size_t from = std::size_t(pair) * (padded_width_ / 2) + x0 / 2;
        const int bytes = (x1 + 1) / 2 - x0 / 2;
        std::memcpy(out.data[1] + std::ptrdiff_t(pair) * out.linesize[1] + x0 / 2, u_.data() + from, bytes);
        std::memcpy(out.data[2] + std::ptrdiff_t(pair) * out.linesize[2] + x0 / 2, v_.data() + from, bytes);
      }
      block = end;
    }
  }
}

namespace {
// The conversion of a stretch of rows, in loops a compiler can vectorize
// (no aliasing, one pixel or one 2x2 block per iteration); built for AVX2
// beside the baseline, the faster chosen when the program starts.
[[gnu::target_clones("avx2", "default")]] void luma_row(const std::uint32_t* __restrict in,
                                                          std::uint8_t* __restrict out, int n) {
  for (int x = 0; x < n; ++x) out[x] = luma(in[x]);
}

[[gnu::target_clones("avx2", "default")]] void chroma_row(const std::uint32_t* __restrict top,
                                                            const std::uint32_t* __restrict bottom,
                                                            std::uint8_t* __restrict u, std::uint8_t* __restrict v,
                                                            int pairs) {
  constexpr int kChromaRound = 1 << (kShift + 1), kChromaOffset = 128 << (kShift + 2);
  for (int i = 0; i < pairs; ++i) {
    const std::uint32_t a = top[2 * i], b = top[2 * i + 1], c = bottom[2 * i], d = bottom[2 * i + 1];
    const int r = red(a) + red(b) + red(c) + red(d);
    const int g = green(a) + green(b) + green(c) + green(d);
    const int bl = blue(a) + blue(b) + blue(c) + blue(d);
    u[i] = static_cast<std::uint8_t>((kUr * r + kUg * g + kUb * bl + kChromaOffset + kChromaRound) >> (kShift + 2));
    v[i] = static_cast<std::uint8_t>((kVr * r + kVg * g + kVb * bl + kChromaOffset + kChromaRound) >> (kShift + 2));
  }
}
}  // namespace

void Yuv420Converter::convert_block(int pair, int x0, int x1) {
  const std::uint32_t* top = previous_.data() + std::size_t(2 * pair) * padded_width_;
  const std::uint32_t* bottom = top + padded_width_;
  std::uint8_t* y_top = y_.data() + std::size_t(2 * pair) * padded_width_;
  std::uint8_t* y_bottom = y_top + padded_width_;
  luma_row(top + x0, y_top + x0, x1 - x0);
  luma_row(bottom + x0, y_bottom + x0, x1 - x0);
  chroma_row(top + x0, bottom + x0, u_.data() + std::size_t(pair) * (padded_width_ / 2) + x0 / 2,
             v_.data() + std::size_t(pair) * (padded_width_ / 2) + x0 / 2, (x1 - x0) / 2);
}

}  // namespace vibra::render
