// vibra concat: joins a render's segment videos into one, in order, without re-encoding.
#pragma once
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "render/encode/join/frame_segment.hpp"

namespace vibra::render {

/// The segment tag a video file carries (see FrameSegment), or nullopt when
/// the file cannot be read or has none.
std::optional<FrameSegment> read_segment_tag(const std::filesystem::path& video);

/// The video file's container "description" (a segment's or a lecture
/// shot's tag); "" when the file cannot be read or has none.
std::string read_video_description(const std::filesystem::path& video);

/// What concat_segments() joined.
struct ConcatSummary {
  long long frames = 0;
  std::size_t parts = 0;
};

/// Joins the segments of one render into `output` by copying their packets,
/// without decoding or encoding. The parts may come in any order. Throws
/// OutputError naming the part that is wrong, before anything is written,
/// when a part is unreadable, is not a segment, comes from another render
/// (its tag's render hash) or another split, has other codec parameters (codec, size, pixel format, time base, frame rate, codec
/// headers), repeats a segment, or when a segment is missing; and while
/// copying, when a part's timestamps are not the frames its tag names. The
/// output is written under a temporary name and renamed when complete.
ConcatSummary concat_segments(const std::vector<std::filesystem::path>& parts, const std::filesystem::path& output);

}  // namespace vibra::render
