// Segments of a render: which frames segment i of n holds, and the tag a segment file carries.
#include "render/encode/join/frame_segment.hpp"

#include <cstdio>
#include <filesystem>

namespace vibra::render {

std::string FrameSegment::tag() const {
  char text[160];
  std::snprintf(text, sizeof text, "vibra segment %lld/%lld: frames %lld-%lld of %lld, render %016llx", index, count,
                first(), end() - 1, total, static_cast<unsigned long long>(render));
  return text;
}

std::optional<FrameSegment> FrameSegment::from_tag(const std::string& text) {
  FrameSegment s;
  long long first = 0, last = 0;
  unsigned long long render = 0;
  int consumed = 0;
  if (std::sscanf(text.c_str(), "vibra segment %lld/%lld: frames %lld-%lld of %lld, render %16llx%n", &s.index, &s.count,
                  &first, &last, &s.total, &render, &consumed) != 6 ||
      consumed != static_cast<int>(text.size()))
    return std::nullopt;
  s.render = render;
  if (s.count < 1 || s.index < 0 || s.index >= s.count || s.total < 1 || s.first() != first || s.end() - 1 != last)
    return std::nullopt;
  return s;
}

std::string FrameSegment::file_name(const std::string& output) const {
  const std::filesystem::path path(output);
  const int width = static_cast<int>(std::to_string(count - 1).size());
  char middle[96];
  std::snprintf(middle, sizeof middle, ".seg-%0*lld-of-%lld", width, index, count);
  return (path.parent_path() / (path.stem().string() + middle + path.extension().string())).string();
}

}  // namespace vibra::render
