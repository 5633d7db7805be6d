// Writes frames to standard output as YUV4MPEG2 (y4m), for pipes into other encoders.
#include "render/encode/y4m_stream.hpp"

#include <cstring>

#include "render/output/output_error.hpp"
#include "render/output/standard_output.hpp"

namespace vibra::render {

namespace {
constexpr char kFrameTag[] = "FRAME\n";
constexpr std::size_t kFrameTagSize = sizeof kFrameTag - 1;
}  // namespace

std::string Y4mStream::header(int width, int height, int fps) {
  return "YUV4MPEG2 W" + std::to_string(width) + " H" + std::to_string(height) + " F" + std::to_string(fps) +
         ":1 Ip A1:1 C420jpeg XYSCSS=420JPEG XCOLORRANGE=LIMITED\n";
}

Y4mStream::Y4mStream(int width, int height, int fps)
    : converter_(width, height, width, height), header_(header(width, height, fps)), width_(width), height_(height) {
  if (fps < 1 || fps > 240) throw OutputError("video fps " + std::to_string(fps) + " is out of range: choose 1..240");
  const std::size_t luma = std::size_t(width) * height;
  const std::size_t chroma = std::size_t((width + 1) / 2) * ((height + 1) / 2);
  frame_.resize(kFrameTagSize + luma + 2 * chroma);
  std::memcpy(frame_.data(), kFrameTag, kFrameTagSize);
}

void Y4mStream::write(const std::uint8_t* argb32, int stride, const Damage* changed) {
  std::uint8_t* y = frame_.data() + kFrameTagSize;
  std::uint8_t* u = y + std::size_t(width_) * height_;
  std::uint8_t* v = u + std::size_t((width_ + 1) / 2) * ((height_ + 1) / 2);
  const int chroma_width = (width_ + 1) / 2;
  converter_.convert(argb32, stride, {{y, u, v}, {width_, chroma_width, chroma_width}}, changed, &frame_holds_);
  if (frames_ == 0) write_standard_output(header_.data(), header_.size());
  write_standard_output(frame_.data(), frame_.size());
  ++frames_;
}

}  // namespace vibra::render
