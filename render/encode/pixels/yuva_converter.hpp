// BGRA to YUVA 4:2:0 (BT.709) for videos with an alpha plane (--transparent).
#pragma once
#include <cstdint>

namespace vibra::render {

/// Four planes to write a picture with alpha into (as in an AVFrame): Y, U, V, A.
struct YuvaPlanes {
  std::uint8_t* data[4];
  int linesize[4];
};

/// Converts Cairo ARGB32 frames with transparency to YUV with an alpha plane,
/// for the two formats that carry it: 8-bit 4:2:0 (VP9 in WebM, yuva420p)
/// and 10-bit 4:4:4 (ProRes 4444, yuva444p10le). BT.709 matrix, limited
/// range, as the opaque Yuv420Converter; alpha is full range.
///
/// Cairo premultiplies colour by alpha; video stores straight colour, so each
/// pixel is divided by its alpha. A 2x2 chroma block averages its pixels'
/// colours weighted by their alpha, so a half-covered edge keeps the colour
/// of the line rather than fading towards the black of empty pixels. Where
/// nothing is drawn (alpha 0) the colour is black and the alpha 0.
///
/// The opaque converter keeps the last frame and converts only what changed;
/// transparent output is for editing, not speed, so this one converts whole frames.
class YuvaConverter {
 public:
  enum class Layout { yuva420p, yuva444p10 };

  /// Frames of width x height (1..8192); 4:2:0 chroma is half of that rounded up.
  YuvaConverter(Layout, int width, int height);

  void convert(const std::uint8_t* argb32, int stride, const YuvaPlanes& out) const;

 private:
  void convert_420(const std::uint8_t* argb32, int stride, const YuvaPlanes& out) const;
  void convert_444_10(const std::uint8_t* argb32, int stride, const YuvaPlanes& out) const;
  Layout layout_;
  int width_, height_;
};

}  // namespace vibra::render
