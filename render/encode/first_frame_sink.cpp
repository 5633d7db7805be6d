// FirstFrameSink: passes frames on to another sink and keeps the first one as a PNG (a shot's still for slides).
#include "render/encode/first_frame_sink.hpp"

#include <cstdio>

#include "render/encode/png/png_encoder.hpp"
#include "render/output/output_error.hpp"

namespace vibra::render {

FirstFrameSink::FirstFrameSink(std::unique_ptr<FrameSink> inner, std::filesystem::path png, int width, int height)
    : inner_(std::move(inner)), png_path_(std::move(png)), width_(width), height_(height) {}

void FirstFrameSink::write(const std::uint8_t* bgra, int stride, const Damage* changed) {
  if (png_.empty()) png_ = encode_png(bgra, width_, height_, stride);
  inner_->write(bgra, stride, changed);
}

void FirstFrameSink::finish() {
  const std::string name = png_path_.string();
  if (png_.empty()) throw OutputError("no frame came for '" + name + "': a shot needs at least one frame");
  std::FILE* f = std::fopen(name.c_str(), "wb");
  if (!f) throw OutputError("cannot write '" + name + "': choose a writable folder");
  const bool ok = std::fwrite(png_.data(), 1, png_.size(), f) == png_.size();
  if (std::fclose(f) != 0 || !ok) throw OutputError("writing '" + name + "' failed (disk full?)");
  inner_->finish();
}

}  // namespace vibra::render
