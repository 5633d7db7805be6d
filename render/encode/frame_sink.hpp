// FrameSink: where rendered frames go (a PNG sequence or a video file), and the video settings of the command line.
#pragma once
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "render/draw/damage.hpp"

namespace vibra::render {

/// Where rendered frames go: a PNG sequence or a video file. write() takes
/// Cairo ARGB32 pixels; finish() completes the output (flush, trailer,
/// rename into place) and throws OutputError on failure. Destroying an
/// unfinished sink removes what it wrote: no partial output remains.
class FrameSink {
 public:
  virtual ~FrameSink() = default;
  /// `changed`: where the frame may differ from the last one, if known (else nullptr).
  virtual void write(const std::uint8_t* bgra, int stride, const Damage* changed) = 0;
  virtual void finish() = 0;
  /// The next frame starts a chapter (a lecture's shot): a video codes it as
  /// a keyframe; frames in files need nothing.
  virtual void start_keyframe() {}
  /// Things to tell the user once (e.g. a size rounded up for H.264).
  virtual std::vector<std::string> notes() const { return {}; }
  /// What was written, for the closing message.
  virtual std::string description() const = 0;
};

/// Video settings from the command line.
struct VideoSettings {
  std::string codec;    ///< "" = from the extension
  std::string quality = "medium";
  int crf = -1;
  std::string preset;
  int threads = 0;  ///< PNG compression and encoder threads; 0 = one per core
  bool transparent = false;  ///< keep alpha (frames drawn without a background)
  /// With the output "-" (standard output): y4m (raw frames), nut or matroska.
  std::string format;
};

/// True when `output` names a video file (.mp4, .webm, .mkv, .ogv, .gif, .flv).
bool is_video_path(const std::string& output);
/// True when `output` is a PNG frame pattern (has %d) or a directory.
bool is_frame_pattern(const std::string& output);

/// Checks what VideoSettings ask of `output` before a run: a stream ("-", a
/// pipe or device: `stream`) needs a stream format and cannot be
/// transparent; --format is for streams only; a transparent video must be
/// .webm or .mov. Throws OutputError naming the fix.
void check_output_settings(const std::string& output, bool stream, const VideoSettings&);

/// Throws OutputError unless `format` is one standard output can take
/// (y4m, nut, matroska), naming them.
void require_stream_format(const std::string& format);

/// The sink for `output`: a video file, a PNG frame pattern / directory, or
/// "-" for standard output in VideoSettings::format.
/// `frame_count`: frames of the whole render (it sets the names' digits);
/// `first_frame`: the first one this sink gets (a segment's), the first
/// frame's number or timestamp.
std::unique_ptr<FrameSink> make_frame_sink(const std::string& output, int width, int height, double fps,
                                           long long frame_count, const VideoSettings&,
                                           const std::map<std::string, std::string>& metadata,
                                           long long first_frame = 0);

/// The sink for every one of `outputs` (as make_frame_sink): the one sink
/// when there is one, else one that writes each frame to all (a page's MP4
/// and WebM: draw once, encode twice).
std::unique_ptr<FrameSink> make_frame_sinks(const std::vector<std::string>& outputs, int width, int height, double fps,
                                            long long frame_count, const VideoSettings&,
                                            const std::map<std::string, std::string>& metadata,
                                            long long first_frame = 0);

}  // namespace vibra::render
