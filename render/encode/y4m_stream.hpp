// Writes frames to standard output as YUV4MPEG2 (y4m), for pipes into other encoders.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "render/draw/damage.hpp"
#include "render/encode/pixels/yuv420_converter.hpp"

namespace vibra::render {

/// Writes frames to standard output as YUV4MPEG2 (y4m): a header line, then
/// per frame "FRAME" and the Y, U, V planes of 4:2:0, 8 bits. Raw frames need
/// no decoder, so a player shows them as they come: `vibra render -o -
/// --format y4m | ffplay -`. The conversion is the opaque video path's
/// (Yuv420Converter: BT.709, limited range, only what changed), tagged
/// C420jpeg (chroma centred in each 2x2 block) and XCOLORRANGE=LIMITED.
///
/// Every write is checked: a failed one throws StandardOutputFailed
/// (standard_output.hpp).
class Y4mStream {
 public:
  /// Frames of width x height (1..8192) at `fps` frames per second.
  Y4mStream(int width, int height, int fps);

  /// Converts and writes one Cairo ARGB32 frame; `changed` as for Yuv420Converter.
  void write(const std::uint8_t* argb32, int stride, const Damage* changed = nullptr);
  long long frames_written() const { return frames_; }

  /// The header line, e.g. "YUV4MPEG2 W1280 H720 F30:1 Ip A1:1 C420jpeg XYSCSS=420JPEG XCOLORRANGE=LIMITED\n".
  static std::string header(int width, int height, int fps);

 private:
  Yuv420Converter converter_;
  std::string header_;
  std::vector<std::uint8_t> frame_;  ///< "FRAME\n" and the planes, written at once
  std::uint64_t frame_holds_ = 0;    ///< which conversion frame_ holds
  int width_, height_;
  long long frames_ = 0;
};

}  // namespace vibra::render
