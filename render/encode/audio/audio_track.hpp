// AudioTrack: a lecture's sound encoded as a stream of a muxed file (AAC in MP4, Opus in WebM), written in step with its video.
#pragma once
extern "C" {
#include <libavcodec/avcodec.h>
}

#include <memory>

#include "render/encode/audio/audio_clip.hpp"
#include "render/encode/join/remux_files.hpp"

namespace vibra::render {

/// The sound of a joined video. Made before the header is written; then
/// write_until() encodes the sound up to a time as the video's packets pass
/// it, so the muxer interleaves the two, and finish() encodes the rest.
class AudioTrack {
 public:
  /// AAC (FFmpeg's own encoder) for MP4, Opus (libopus) for WebM and Matroska.
  /// Throws OutputError when this FFmpeg lacks the encoder.
  AudioTrack(MuxedOutput& out, const AudioClip& sound, bool mp4);
  ~AudioTrack();
  AudioTrack(const AudioTrack&) = delete;
  AudioTrack& operator=(const AudioTrack&) = delete;
  /// Encodes and writes the sound's samples before `seconds`.
  void write_until(double seconds);
  /// Encodes the rest (the last frame padded with silence) and drains the encoder.
  void finish();

 private:
  void encode(const AVFrame* frame);
  MuxedOutput& out_;
  const AudioClip& sound_;
  AVCodecContext* codec_ = nullptr;
  AVStream* stream_ = nullptr;
  AVFrame* frame_ = nullptr;
  AVPacket* packet_ = nullptr;
  std::size_t next_ = 0;  ///< the next sample to encode
};

}  // namespace vibra::render
