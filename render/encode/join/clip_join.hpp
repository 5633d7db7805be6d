// Joins a lecture's clips into one video with chapters and subtitle streams, copying packets without re-encoding.
#pragma once
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "render/encode/audio/audio_clip.hpp"
#include "render/encode/subtitle_cue.hpp"

namespace vibra::render {

/// A chapter of a joined video: frames [first_frame, end_frame).
struct VideoChapter {
  std::string title;
  long long first_frame = 0, end_frame = 0;
};

/// A video to join, and how many frames it must hold (a shot's, or all the
/// shots' when they were encoded as one).
struct ClipFile {
  std::filesystem::path path;
  long long frames = 0;
};

/// Joins `clips` (videos of one size, frame rate and codec setup, each
/// starting at frame 0, as vibra renders them) one after the other into
/// `output` (.mp4 or .webm) by copying their packets, without decoding.
/// Adds `chapters` (MP4 and Matroska chapters, as ffprobe -show_chapters
/// lists them) and, when there are cues, a soft subtitle track: mov_text in
/// MP4, WebVTT in WebM. `fps` is the clips' frame rate. Throws OutputError
/// naming the clip (one that does not hold its frames) or the output; the
/// output is written under a temporary name and renamed when complete.
/// `sound`, when given, is encoded as an audio track from the video's start
/// (AAC in MP4, Opus in WebM: audio_track.hpp), interleaved with the frames.
void join_clips(const std::vector<ClipFile>& clips, const std::filesystem::path& output, int fps,
                const std::vector<VideoChapter>& chapters, const std::vector<SubtitleCue>& cues,
                const std::map<std::string, std::string>& metadata, const AudioClip* sound = nullptr);

}  // namespace vibra::render
