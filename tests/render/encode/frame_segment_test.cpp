// Segments of a render: which frames each holds, the tag a segment file
// carries, and the segment file's name.
#include <catch2/catch.hpp>

#include "render/encode/join/frame_segment.hpp"

using vibra::render::FrameSegment;

TEST_CASE("segments cover every frame once, in order, within one frame of each other's length", "[segment]") {
  for (long long total : {1LL, 2LL, 7LL, 31LL, 100LL, 1001LL})
    for (long long count = 1; count <= std::min(total, 12LL); ++count) {
      INFO(total << " frames in " << count << " segments");
      long long next = 0, shortest = total, longest = 0;
      for (long long k = 0; k < count; ++k) {
        const FrameSegment s{k, count, total};
        CHECK(s.first() == next);
        next = s.end();
        shortest = std::min(shortest, s.frames()), longest = std::max(longest, s.frames());
      }
      CHECK(next == total);
      CHECK(longest - shortest <= 1);
      CHECK(shortest >= 1);
    }
  CHECK(FrameSegment{1, 3, 300}.first() == 100);
  CHECK(FrameSegment{1, 3, 300}.end() == 200);
  CHECK(FrameSegment{2, 3, 31}.first() == 20);
}

TEST_CASE("a segment's tag reads back as the same segment, and other text is no tag", "[segment]") {
  const FrameSegment s{1, 3, 300, 0x00c0ffee12345678};
  CHECK(s.tag() == "vibra segment 1/3: frames 100-199 of 300, render 00c0ffee12345678");
  CHECK(FrameSegment::from_tag(s.tag()) == s);
  CHECK(FrameSegment::from_tag(FrameSegment{0, 1, 1, ~0ull}.tag()) == FrameSegment{0, 1, 1, ~0ull});
  for (const char* text : {"", "vibra segment", "vibra segment 1/3: frames 100-199 of 300, render 1 extra",
                           "vibra segment 1/3: frames 100-199 of 300",            // no render
                           "vibra segment 3/3: frames 300-299 of 300, render 1",  // K out of range
                           "vibra segment 1/3: frames 101-199 of 300, render 1",  // range not the split's
                           "vibra segment 0/0: frames 0-0 of 1, render 1", "a lecture on pendulums"})
    CHECK_FALSE(FrameSegment::from_tag(text).has_value());
}

TEST_CASE("a segment's file sits beside the output, numbered so that the names sort", "[segment]") {
  CHECK(FrameSegment{1, 3, 30}.file_name("out/lecture.mp4") == "out/lecture.seg-1-of-3.mp4");
  CHECK(FrameSegment{7, 12, 300}.file_name("lecture.webm") == "lecture.seg-07-of-12.webm");
  CHECK(FrameSegment{0, 1, 30}.file_name("a.b.mkv") == "a.b.seg-0-of-1.mkv");
}
