// The video codecs and containers vibra writes, as tables: one row per codec (encoder, quality, pixels, tuning) and per container.
#pragma once
extern "C" {
#include <libavcodec/avcodec.h>
}

#include <array>
#include <filesystem>
#include <string>

namespace vibra::render {

/// What a codec's tuning sets: the encoder's context and private options,
/// given the quality chosen (crf, or quantizer) and the user's preset.
struct EncoderSetup {
  AVCodecContext* context;
  AVDictionary** options;
  int quality;
  bool lossless;
  const std::string& preset;  ///< "" = vibra's default tuning
};

/// One codec, as VideoOptions::codec names it. Quality presets are for
/// {draft, medium, high}; lowest..highest the explicit --crf accepted (0..0:
/// the codec has no quality setting).
struct Codec {
  const char* name;
  const char* label;    ///< for messages
  const char* encoder;  ///< FFmpeg encoder name
  std::array<int, 3> quality;
  int lowest, highest;
  AVPixelFormat pixels;        ///< opaque frames
  AVPixelFormat alpha_pixels;  ///< transparent frames; AV_PIX_FMT_NONE: no alpha
  bool always_alpha;           ///< its frames always carry alpha (ProRes 4444)
  bool even_size;              ///< sizes rounded up to even (x264 in 4:2:0)
  bool lossless;               ///< --quality lossless exists
  const char* const* presets;  ///< the encoder's own --preset names, nullptr-terminated; nullptr: none
  const char* presets_of;      ///< whose presets they are, for messages ("x264")
  int smooth_fps;              ///< viewers slow down faster frames (GIF); 0: no limit
  const char* fallback;        ///< the extension to suggest when the encoder is missing
  void (*tune)(const EncoderSetup&);
};

/// One container, by the file extension that names it.
struct Container {
  const char* extension;
  const char* format;     ///< FFmpeg muxer name
  const char* codec;      ///< default codec
  const char* movflags;   ///< the muxer's movflags, or nullptr
  bool streams;           ///< may go to standard output (-o - --format)
};

/// The codec named `name`; throws OutputError listing the codecs.
const Codec& find_codec(const std::string& name);
/// The container for a path's extension (any case), or nullptr.
const Container* container_for(const std::filesystem::path&);
/// The container for a path; throws OutputError listing the extensions.
const Container& find_container(const std::filesystem::path&);
/// A container that may stream, by its muxer name (--format nut), or nullptr.
const Container* streaming_container(const std::string& format);
/// Whether the codec can carry alpha.
bool carries_alpha(const Codec&);
/// "A or B" of the labels of the codecs that `has` something, for messages.
std::string codec_labels(bool (*has)(const Codec&));
/// "a, b or c": the codec's own --preset names.
std::string preset_names(const Codec&);

}  // namespace vibra::render
