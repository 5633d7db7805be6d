// VideoWriter: frames converted to YUV and encoded by libavcodec on its own thread into a libavformat container.
#pragma once
#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "render/draw/damage.hpp"

namespace vibra::render {

enum class VideoQuality { draft, medium, high, lossless };

struct VideoOptions {
  int width = 1280, height = 720;  ///< size of the frames passed to write(), pixels
  int fps = 30;                    ///< frames per second, 1..240
  std::string codec;               ///< "" = from the extension; or h264, vp9, vp8, theora, gif, flv
  VideoQuality quality = VideoQuality::medium;
  int crf = -1;                    ///< -1 = from quality; else the encoder's crf (quantizer for theora, flv)
  std::string preset;              ///< x264 preset; "" = veryfast without B-frames (measured best for line art)
  int threads = 0;                 ///< encoder threads; 0 = the codec's default for this machine
  std::map<std::string, std::string> metadata;  ///< container metadata: title, comment, description
  /// Timestamp of the first frame, in frames: a segment of a longer render
  /// starts at its first frame's index (and, as every video, with a key frame).
  long long first_frame = 0;
  /// Keep the frames' alpha: VP9 in .webm (yuva420p) or ProRes 4444 in .mov;
  /// any other format refuses it (alpha_problem says why).
  bool transparent = false;
  /// The container for the path "-" (standard output): "nut" or "matroska".
  std::string format;
};

/// Encodes Cairo frames into a video file in process with FFmpeg's libraries,
/// following FFmpeg's doc/examples/mux.c. write() converts each frame (to
/// BT.709 limited-range YUV 4:2:0, or to a fixed palette for GIF) on the
/// caller's thread, and a worker thread encodes behind a bounded queue, so
/// drawing and converting the next frame overlap encoding this one. The file
/// is written under a temporary name and renamed by finish(): a failed or
/// abandoned writer leaves nothing at the final path. The path "-" streams
/// to standard output (VideoOptions::format names the container); a failed
/// write there ends the writer with StandardOutputFailed (standard_output.hpp).
class VideoWriter {
 public:
  /// Throws OutputError for an unknown extension or codec, a missing encoder,
  /// a bad size, fps or crf, or an unwritable path.
  VideoWriter(const std::filesystem::path& final_path, const VideoOptions&);
  VideoWriter(const VideoWriter&) = delete;
  VideoWriter& operator=(const VideoWriter&) = delete;
  /// Unfinished: stops the worker and removes the temporary file. Never throws.
  ~VideoWriter();

  /// Converts and queues one frame of Cairo ARGB32 pixels (width x height,
  /// `stride` bytes per row; premultiplied alpha, so transparency comes out
  /// black). Waits only while the queue is full. Throws OutputError for a
  /// failure the worker met since the last call. `changed`, if given, says
  /// where the frame may differ from the last one: only there is it converted.
  void write(const std::uint8_t* argb32, int stride, const Damage* changed = nullptr);
  /// The next frame written starts a chapter: it is coded as a keyframe, so
  /// that a player seeking to the chapter starts there.
  void start_keyframe() { keyframe_next_ = true; }
  /// Encodes what is queued, flushes the encoder, writes the trailer and
  /// renames the file into place. Throws OutputError (e.g. disk full).
  void finish();
  int frames_written() const { return frames_; }
  /// The file the video goes to (a link's target); empty for standard output.
  std::filesystem::path file() const;
  /// Things to tell the user once, e.g. a size rounded up to even.
  const std::vector<std::string>& notes() const { return notes_; }

  /// The codec an output name implies; throws OutputError listing the supported extensions.
  static std::string codec_for_path(const std::filesystem::path&);
  /// Whether the output name's extension is one of the video formats.
  static bool is_video_path(const std::filesystem::path&);
  /// Why `path` (with `codec`, "" = its default) cannot hold transparency,
  /// naming the formats that can; "" when it can.
  static std::string alpha_problem(const std::filesystem::path&, const std::string& codec);
  /// The path that means standard output.
  static constexpr const char* kStandardOutput = "-";

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  int frames_ = 0;
  bool finished_ = false;
  bool keyframe_next_ = false;
  std::vector<std::string> notes_;
};

}  // namespace vibra::render
