// classify_output: the kind of output from its name, by the rules every command shares.
#include "render/encode/output_kind.hpp"

#include "render/encode/frame_sink.hpp"

namespace vibra::render {

OutputKind classify_output(const std::string& name) {
  if (name == "-") return OutputKind::stream;
  const std::string ext = lower_extension_of(name);
  if (ext == ".html") return OutputKind::page;
  if (is_video_path(name)) return OutputKind::video;
  if (!name.empty() && is_frame_pattern(name)) return OutputKind::frames;
  if (ext == ".png" || ext == ".svg" || ext == ".pdf") return OutputKind::picture;
  return OutputKind::unknown;
}

}  // namespace vibra::render
