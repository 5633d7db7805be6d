// FirstFrameSink: passes frames on to another sink and keeps the first one as a PNG (a shot's still for slides).
#pragma once
#include <cstdint>
#include <filesystem>
#include <memory>
#include <vector>

#include "render/encode/frame_sink.hpp"

namespace vibra::render {

/// Every frame goes on to `inner`; the first is also encoded as PNG, the
/// very picture drawn (no video coding in between), and written to `png`
/// by finish(), before `inner` finishes. Throws OutputError when the PNG
/// cannot be written, or when no frame came.
class FirstFrameSink final : public FrameSink {
 public:
  FirstFrameSink(std::unique_ptr<FrameSink> inner, std::filesystem::path png, int width, int height);
  void write(const std::uint8_t* bgra, int stride, const Damage* changed) override;
  void finish() override;
  void start_keyframe() override { inner_->start_keyframe(); }
  std::vector<std::string> notes() const override { return inner_->notes(); }
  std::string description() const override { return inner_->description(); }

 private:
  std::unique_ptr<FrameSink> inner_;
  std::filesystem::path png_path_;
  int width_, height_;
  std::vector<std::uint8_t> png_;  ///< the first frame, encoded; empty until it comes
};

}  // namespace vibra::render
