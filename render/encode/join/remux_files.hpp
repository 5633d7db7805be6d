// The files of a remux (packets copied without decoding): an input opened with libavformat, an output written under a temporary name, and the check that two video streams can follow each other in one file.
#pragma once
extern "C" {
#include <libavformat/avformat.h>
}

#include <filesystem>
#include <memory>
#include <string>

#include "render/output/temporary_file.hpp"

namespace vibra::render {

struct InputCloser {
  void operator()(AVFormatContext* c) const { avformat_close_input(&c); }
};
using MediaInput = std::unique_ptr<AVFormatContext, InputCloser>;

/// The file opened for reading; null with `error` set (FFmpeg's reason) when it cannot be.
MediaInput open_media_input(const std::filesystem::path&, std::string& error);

/// A container metadata value ("" when absent).
std::string container_metadata(const AVFormatContext*, const char* key);

/// 'PATH', for messages.
std::string quoted_path(const std::filesystem::path&);

/// The video stream's frame rate (average, else real); {0, 1} when it has none.
AVRational stream_frame_rate(const AVStream*);

/// The first codec parameter in which stream `b` differs from stream `a`
/// (codec, size, pixel format, time base, frame rate, codec headers, colour
/// space), in words; "" when they can follow each other in one stream.
std::string differing_video_parameter(const AVStream* a, const AVStream* b);

/// A file being written by a muxer, under a temporary name until commit().
struct MuxedOutput {
  TemporaryFile file;
  AVFormatContext* format = nullptr;

  explicit MuxedOutput(const std::filesystem::path& path) : file(path) {}
  MuxedOutput(const MuxedOutput&) = delete;
  MuxedOutput& operator=(const MuxedOutput&) = delete;
  ~MuxedOutput();
  /// Throws OutputError naming the file and `what` unless `code` is a success.
  void check(int code, const std::string& what) const;
  /// Allocates the muxer for `muxer` and opens the temporary file.
  void open(const AVOutputFormat* muxer);
  /// Writes the header (MP4: the index first, +faststart).
  void write_header();
  /// Writes the trailer, closes the file and renames it into place.
  void finish_and_commit();
};

}  // namespace vibra::render
