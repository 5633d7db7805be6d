// Segments of a render: which frames segment i of n holds, and the tag a segment file carries.
#pragma once
#include <cstdint>
#include <optional>
#include <string>

namespace vibra::render {

/// Segment `index` of `count` of a render of `total` frames: the frames
/// [index * total / count, (index + 1) * total / count). Segments of one
/// render cover its frames exactly once, in order, and differ in length by at
/// most one frame. A segment file carries its tag (tag()) in the container's
/// "description", so that `vibra concat` can check what each part holds.
struct FrameSegment {
  long long index = 0, count = 1, total = 0;
  /// Tells renders apart: a hash of everything that shapes the frames and
  /// their coding (scene, parameters, size, timing, video options).
  std::uint64_t render = 0;

  long long first() const { return index * total / count; }
  long long end() const { return (index + 1) * total / count; }  ///< one past the last frame
  long long frames() const { return end() - first(); }

  /// E.g. "vibra segment 1/3: frames 100-199 of 300, render 00c0ffee00c0ffee".
  std::string tag() const;
  /// The segment a tag describes; nullopt for any other text.
  static std::optional<FrameSegment> from_tag(const std::string&);
  /// A segment's file beside `output`: "lecture.mp4" -> "lecture.seg-1-of-3.mp4"
  /// (K zero-padded to N's width, so the names sort).
  std::string file_name(const std::string& output) const;

  bool operator==(const FrameSegment&) const = default;
};

}  // namespace vibra::render
