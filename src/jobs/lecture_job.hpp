// The lecture job: a storyboard's shots rendered into one video with chapters and subtitles.
#pragma once
#include <optional>
#include <string>

#include "render/encode/join/frame_segment.hpp"
#include "render/encode/frame_sink.hpp"

namespace vibra::scenes {

struct LectureRequest {
  std::string storyboard;  ///< the TOML file of shots
  std::string output;      ///< OUT.mp4, OUT.webm or OUT.html
  /// Render this shot alone (1, 2, ...) into the output, with its chapter and subtitles.
  std::optional<int> shot;
  /// Render only the shots S with (S - 1) mod count == index, each into a
  /// shot file beside the output (OUT.shot-S.EXT), for a cluster; a later
  /// run without it joins them instead of rendering them again.
  std::optional<render::FrameSegment> segment;
  render::VideoSettings video;
  /// WxH instead of the storyboard's size ("" = the storyboard's): drafts, previews.
  std::string size;
  /// OUT.html is a presentation: a slide a shot, each shot's video and first
  /// frame in OUT_files/, the shots waiting for the presenter's keys.
  bool present = false;
  /// A folder for every shot as its own video and first-frame PNG, with
  /// index.md and beamer.tex ("" = none); rendered once with the other outputs.
  std::string shots_dir;
  /// Replace subtitles or shot files that vibra did not write for this lecture.
  bool force = false;
  bool quiet = false;
  bool mute = false;    ///< no sound track: the shots keep the lengths their speech gives them
  bool script = false;  ///< write the narration script (shot, title, length, words) to standard output instead
  std::string command_line;  ///< shown on a page
};

/// Reads and checks the whole storyboard (every shot's keys, scene and
/// pacing) before anything is written, renders each shot through the render
/// job (a card is one picture encoded again and again) and joins them into
/// one video with a chapter per shot and the cards and notes as subtitles:
/// a track in the video and OUT.vtt beside it; OUT.html is a page with the
/// MP4, WebM and subtitles in OUT_files/ and a chapter list. Throws
/// UsageError / OutputError / SolutionError / render::Interrupted; then
/// nothing is left at the output paths, and earlier output there is as it was.
void run_lecture(const LectureRequest&);

}  // namespace vibra::scenes
