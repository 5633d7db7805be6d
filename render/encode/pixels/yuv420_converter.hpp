// BGRA to YUV 4:2:0 (BT.709, limited range), converting only the blocks that changed.
#pragma once
#include <cstdint>
#include <vector>

#include "render/draw/damage.hpp"
#include "render/encode/huge_pages.hpp"

namespace vibra::render {

/// Three planes to write a YUV 4:2:0 picture into (as in an AVFrame).
struct Yuv420Planes {
  std::uint8_t* data[3];
  int linesize[3];
};

/// Converts Cairo ARGB32 frames to YUV 4:2:0 with the BT.709 matrix in limited
/// ("tv") range, chroma the mean of each 2x2 block; alpha is ignored, so
/// premultiplied transparency comes out black.
///
/// Between two frames of an animation most of the picture stays the same
/// (ceiling, axes, background), so the converter keeps the last frame and
/// converts only the blocks of 2 rows by 32 columns that changed: comparing
/// costs a fraction of converting, and where the caller says nothing changed
/// (Damage) it does not even compare. The result is exactly that of
/// converting every block.
class Yuv420Converter {
 public:
  /// Frames of width x height (1..8192); the output is out_width x out_height,
  /// each equal to the frame's or one more for an odd one (H.264 needs even
  /// sizes), the extra column or row repeating the last.
  Yuv420Converter(int width, int height, int out_width, int out_height);

  /// Converts one frame (rows `stride` bytes apart) into `out`: luma
  /// out_width x out_height, chroma half of that rounded up. `changed`, if
  /// given, bounds where the frame differs from the last one.
  ///
  /// `out_holds`, if given, says which conversion `out` already holds (a
  /// number this converter gave it before, or 0 for unknown pixels) and is
  /// set to this one's: an encoder's frames come round again, and only the
  /// blocks converted since need copying into them.
  void convert(const std::uint8_t* argb32, int stride, const Yuv420Planes& out, const Damage* changed = nullptr,
               std::uint64_t* out_holds = nullptr);

  /// Blocks converted by the last convert(), of blocks(): for tests and tuning.
  long long converted_blocks() const { return converted_; }
  long long blocks() const;

  static constexpr int kBlockWidth = 32;

 private:
  /// Converts the block at row pair `pair`, columns from x0, if it changed.
  void convert_if_changed(int pair, int x0, const std::uint32_t* top, const std::uint32_t* bottom);
  void convert_block(int pair, int x0, int x1);
  /// Looks at the blocks of row pair `pair` that the spans touch.
  void convert_spans(int pair, const std::uint8_t* argb32, int stride);
  /// Copies the blocks converted after conversion `since` into `out`.
  void copy_out(const Yuv420Planes& out, std::uint64_t since) const;
  int blocks_per_row() const { return (width_ + kBlockWidth - 1) / kBlockWidth; }

  int width_, height_, out_width_, out_height_;
  int padded_width_, padded_height_;  ///< even
  bool first_ = true;
  long long converted_ = 0;
  std::uint64_t conversion_ = 0;               ///< numbers the calls to convert(), from 1
  std::vector<std::uint64_t> block_converted_;  ///< per block: the conversion that last changed it
  HugePageArray<std::uint32_t> previous_;  ///< the last frame, padded to even size (written whole first)
  HugePageArray<std::uint8_t> y_, u_, v_;  ///< its conversion, padded_width_ (/2) wide
  std::vector<std::pair<int, int>> spans_;  ///< scratch: the changed columns of a row pair
  std::vector<int> edges_;                  ///< scratch: row pairs where a damage rectangle starts or ends
};

}  // namespace vibra::render
