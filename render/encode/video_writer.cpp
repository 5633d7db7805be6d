// VideoWriter: frames converted to YUV and encoded by libavcodec on its own thread into a libavformat container.
#include "render/encode/video_writer.hpp"

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/imgutils.h>
}

#include <algorithm>
#include <array>
#include <atomic>
#include <cctype>
#include <cerrno>
#include <condition_variable>
#include <cstring>
#include <deque>
#include <future>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <map>
#include <thread>

#include "render/encode/av_error.hpp"
#include "render/encode/encoder_priority.hpp"
#include "render/encode/huge_pages.hpp"
#include "render/encode/video_formats.hpp"
#include "render/encode/pixels/yuv420_converter.hpp"
#include "render/encode/pixels/yuva_converter.hpp"
#include "render/output/output_error.hpp"
#include "render/output/standard_output.hpp"
#include "render/output/temporary_file.hpp"

namespace fs = std::filesystem;

namespace vibra::render {

namespace {
/// Pixels for `frame` (format and size set) in huge pages (huge_pages.hpp).
/// Unlike av_frame_get_buffer's, the planes follow each other without extra
/// rows: encoders read width x height, and a guard page right after the
/// buffer found no reads past it with libx264, libvpx (VP8, VP9), Theora,
/// FLV1 or GIF. Lines start on 64 bytes, and 64 bytes of slack follow the
/// last one for SIMD loads.
int allocate_frame_pixels(AVFrame* frame) {
  constexpr int kLineAlign = 64, kSlack = 64;
  const auto format = static_cast<AVPixelFormat>(frame->format);
  const int size = av_image_get_buffer_size(format, frame->width, frame->height, kLineAlign);
  if (size < 0) return size;
  void* pixels = nullptr;
  try {
    pixels = allocate_huge_page_memory(std::size_t(size) + kSlack);
  } catch (const std::bad_alloc&) {
    return AVERROR(ENOMEM);
  }
  frame->buf[0] = av_buffer_create(
      static_cast<std::uint8_t*>(pixels), size, [](void*, std::uint8_t* data) { free_huge_page_memory(data); },
      nullptr, 0);
  if (!frame->buf[0]) {
    free_huge_page_memory(pixels);
    return AVERROR(ENOMEM);
  }
  const int filled = av_image_fill_arrays(frame->data, frame->linesize, frame->buf[0]->data, format, frame->width,
                                          frame->height, kLineAlign);
  return filled < 0 ? filled : 0;
}

/// New pixels for a frame an encoder still holds (GIF's keeps its last one):
/// no copy of the old picture, which convert() overwrites whole.
int renew_frame_pixels(AVFrame* frame) {
  const int format = frame->format, width = frame->width, height = frame->height;
  av_frame_unref(frame);
  frame->format = format;
  frame->width = width;
  frame->height = height;
  return allocate_frame_pixels(frame);
}

/// The writer's codec and container, checked against the options.
struct FormatChoice {
  const Container& container;
  const Codec& codec;
  const AVCodec* encoder;
  const AVOutputFormat* muxer;
  bool alpha, lossless;
};

/// A fixed palette suited to line art: a 6x6x6 colour cube (216 colours,
/// black and white among them) and 40 more greys, because anti-aliased dark
/// lines on a light background are mostly greys. Nearest colour without
/// dithering keeps lines and flat areas clean, and a fixed palette lets the
/// GIF keep one global palette. A 6-bit-per-channel table maps pixels fast.
struct GifPalette {
  static constexpr int kGreys = 40;
  std::array<std::uint32_t, 256> colors{};  ///< 0xAARRGGBB, as AV_PIX_FMT_PAL8 wants
  std::vector<std::uint8_t> nearest = std::vector<std::uint8_t>(1 << 18);

  GifPalette() {
    for (int i = 0; i < 216; ++i) colors[i] = argb(i / 36 * 51, i / 6 % 6 * 51, i % 6 * 51);
    for (int i = 0; i < kGreys; ++i) {
      const int v = (i + 1) * 255 / (kGreys + 1);
      colors[216 + i] = argb(v, v, v);
    }
    for (int key = 0; key < (1 << 18); ++key) {
      const int r = expand(key >> 12), g = expand(key >> 6 & 63), b = expand(key & 63);
      const int cube = (r + 25) / 51 * 36 + (g + 25) / 51 * 6 + (b + 25) / 51;
      const int mean = (2 * r + 4 * g + 3 * b + 4) / 9;  // the nearest grey under distance()'s weights
      const int grey = 216 + std::clamp((mean * (kGreys + 1) + 127) / 255 - 1, 0, kGreys - 1);
      nearest[key] = static_cast<std::uint8_t>(
          distance(r, g, b, colors[cube]) <= distance(r, g, b, colors[grey]) ? cube : grey);
    }
  }

  /// The palette index of a native-endian ARGB32 pixel.
  std::uint8_t operator()(std::uint32_t pixel) const {
    return nearest[(pixel >> 6 & 0x3f000) | (pixel >> 4 & 0xfc0) | (pixel >> 2 & 0x3f)];
  }

 private:
  static std::uint32_t argb(int r, int g, int b) { return 0xff000000u | r << 16 | g << 8 | b; }
  static int expand(int six_bits) { return (six_bits * 255 + 31) / 63; }
  static int distance(int r, int g, int b, std::uint32_t c) {
    const int dr = r - int(c >> 16 & 255), dg = g - int(c >> 8 & 255), db = b - int(c & 255);
    return 2 * dr * dr + 4 * dg * dg + 3 * db * db;
  }
};

}  // namespace

/// 'NAME', for messages.
static std::string quoted(const fs::path& path) {
  std::string text = "'";
  text += path.string();
  text += '\'';
  return text;
}

struct VideoWriter::Impl {
  explicit Impl(const fs::path& final_path)
      : streaming(final_path == VideoWriter::kStandardOutput),
        target(streaming ? standard_output_name() : quoted(final_path)) {
    if (!streaming) file.emplace(final_path);
  }
  ~Impl();

  bool streaming;      ///< to standard output, through open_standard_output_io
  std::string target;  ///< for messages
  std::optional<TemporaryFile> file;  ///< a file, not a stream: removed last, after it is closed
  /// Streaming: a write to standard output failed, and was recorded there
  /// (set by check() on either thread; write() and finish() turn the failure
  /// into StandardOutputFailed, for main's check at exit to report).
  mutable std::atomic<bool> output_failed = false;
  AVFormatContext* format = nullptr;
  AVCodecContext* codec = nullptr;
  AVStream* stream = nullptr;
  AVPacket* packet = nullptr;
  std::unique_ptr<Yuv420Converter> converter;
  /// Per frame of the queue: which conversion its pixels hold (see Yuv420Converter::convert).
  std::map<const AVFrame*, std::uint64_t> frame_holds;
  std::unique_ptr<YuvaConverter> alpha_converter;  ///< transparent VP9 and ProRes, beside the opaque path
  std::unique_ptr<GifPalette> palette;
  int width = 0, height = 0;              ///< of the frames passed to write()
  int coded_width = 0, coded_height = 0;  ///< padded to even for H.264
  std::int64_t next_pts = 0;

  std::mutex mutex;
  std::condition_variable changed;
  /// Converted frames: the caller converts into a free one, the worker
  /// encodes it and frees it again. Most encoders copy their input, so a
  /// frame is free once encode() returns; one an encoder still holds (GIF's
  /// keeps its last frame) gets new pixels in convert().
  std::vector<AVFrame*> frames, free_frames;
  std::deque<AVFrame*> queue;  ///< waiting for the worker
  std::size_t capacity = 3;
  bool closing = false, stopping = false;
  std::string failure;  ///< the worker's error, rethrown by write() and finish()
  std::thread worker;

  /// Throws OutputError unless `code` is a success; `output` says whether the
  /// step writes the file, so that the fix names the likely cause.
  void check(int code, const std::string& what, bool output) const;
  void convert(const std::uint8_t* argb32, int stride, const Damage* changed, AVFrame* into);
  void encode(AVFrame* input);
  void work();
  // The constructor's stages, in order.
  void size_frames(const VideoOptions&, const Codec&, std::vector<std::string>& notes);
  void open_encoder(const VideoOptions&, const FormatChoice&);
  void allocate_frames();
  void open_output(const VideoOptions&, const Container&);
  void start_worker();
};

VideoWriter::Impl::~Impl() {
  {
    std::lock_guard lock(mutex);
    stopping = true;
  }
  changed.notify_all();
  if (worker.joinable()) worker.join();
  for (AVFrame*& f : frames) av_frame_free(&f);
  av_packet_free(&packet);
  avcodec_free_context(&codec);
  if (format && streaming) close_standard_output_io(format->pb);
  else if (format) avio_closep(&format->pb);
  avformat_free_context(format);
}

void VideoWriter::Impl::check(int code, const std::string& what, bool output) const {
  if (code >= 0) return;
  if (streaming && standard_output_error() != 0) {
    output_failed = true;
    throw OutputError("standard output failed");
  }
  std::string fix;
  if (code == AVERROR(ENOSPC) || code == AVERROR(EDQUOT))
    fix = "free some disk space or choose another directory";
  else if (code == AVERROR(EFBIG))
    fix = "the file size limit was reached: raise it (ulimit -f) or lower the quality";
  else if (output)
    fix = "check that the disk is writable and has space, or choose another directory";
  else
    fix = "try the default quality and preset, or another format";
  throw OutputError("cannot write video to " + target + ": " + what + " failed (" +
                    av_error(code) + "): " + fix);
}

/// Runs on the caller's thread, beside the encoder's: conversion is the
/// copy of the caller's pixels that is needed anyway.
void VideoWriter::Impl::convert(const std::uint8_t* argb32, int stride, const Damage* changed, AVFrame* into) {
  std::uint64_t& holds = frame_holds[into];
  if (!av_frame_is_writable(into)) {
    check(renew_frame_pixels(into), "preparing a frame", false);
    holds = 0;  // new pixels: nothing known of them
  }
  if (palette) {
    for (int y = 0; y < height; ++y) {
      const auto* in = reinterpret_cast<const std::uint32_t*>(argb32 + std::ptrdiff_t(y) * stride);
      std::uint8_t* out = into->data[0] + std::ptrdiff_t(y) * into->linesize[0];
      for (int x = 0; x < width; ++x) out[x] = (*palette)(in[x]);
    }
    std::memcpy(into->data[1], palette->colors.data(), sizeof palette->colors);
  } else if (alpha_converter) {
    alpha_converter->convert(argb32, stride,
                             {{into->data[0], into->data[1], into->data[2], into->data[3]},
                              {into->linesize[0], into->linesize[1], into->linesize[2], into->linesize[3]}});
  } else {
    converter->convert(argb32, stride,
                       {{into->data[0], into->data[1], into->data[2]},
                        {into->linesize[0], into->linesize[1], into->linesize[2]}},
                       changed, &holds);
  }
  into->pts = next_pts++;
}

/// Sends one frame (nullptr: flush) and writes every packet that comes out.
void VideoWriter::Impl::encode(AVFrame* input) {
  check(avcodec_send_frame(codec, input), "encoding", false);
  for (;;) {
    const int got = avcodec_receive_packet(codec, packet);
    if (got == AVERROR(EAGAIN) || got == AVERROR_EOF) return;
    check(got, "encoding", false);
    packet->duration = 1;  // one tick of 1/fps, so the last frame lasts as long as the others
    av_packet_rescale_ts(packet, codec->time_base, stream->time_base);
    packet->stream_index = stream->index;
    check(av_interleaved_write_frame(format, packet), "writing a frame", true);
  }
}

void VideoWriter::Impl::work() {
  std::unique_lock lock(mutex);
  for (;;) {
    changed.wait(lock, [&] { return stopping || closing || !queue.empty(); });
    if (stopping || queue.empty()) return;  // abandoned, or closing with everything encoded
    AVFrame* frame = queue.front();
    queue.pop_front();
    lock.unlock();
    changed.notify_all();  // room in the queue
    try {
      encode(frame);
    } catch (const std::exception& e) {
      lock.lock();
      failure = e.what();
      changed.notify_all();
      return;
    }
    lock.lock();
    free_frames.push_back(frame);
  }
}

std::string VideoWriter::codec_for_path(const fs::path& path) { return find_container(path).codec; }

bool VideoWriter::is_video_path(const fs::path& path) { return container_for(path) != nullptr; }

std::string VideoWriter::alpha_problem(const fs::path& path, const std::string& codec) {
  const Container* container = container_for(path);
  if (!container || carries_alpha(find_codec(codec.empty() ? container->codec : codec))) return "";
  return (codec.empty() ? path.extension().string() + " video" : "--codec " + codec) +
         " cannot be transparent: write .webm (VP9 with alpha), .mov (ProRes 4444 with alpha) or PNG frames such as "
         "frames/tmp_%04d.png";
}

namespace {
void check_size_and_rate(const VideoOptions& o) {
  if (o.width < 1 || o.height < 1 || o.width > 8192 || o.height > 8192)
    throw OutputError("video size " + std::to_string(o.width) + "x" + std::to_string(o.height) +
                      " is out of range: width and height must be 1..8192");
  if (o.fps < 1 || o.fps > 240)
    throw OutputError("video fps " + std::to_string(o.fps) + " is out of range: choose 1..240");
}

const Container& container_of(const fs::path& final_path, const VideoOptions& o) {
  if (final_path != VideoWriter::kStandardOutput) return find_container(final_path);
  const Container* named = streaming_container(o.format);
  if (!named) throw OutputError("-o - streams a video to standard output: add --format y4m, nut or matroska");
  return *named;
}

/// Refuses a quality, preset or transparency the codec cannot give; notes what it ignores.
void check_codec_options(const Codec& codec, const VideoOptions& o, std::vector<std::string>& notes) {
  const bool has_quality = codec.highest > 0, lossless = o.quality == VideoQuality::lossless;
  if (o.crf >= 0 && has_quality && (o.crf < codec.lowest || o.crf > codec.highest))
    throw OutputError("crf " + std::to_string(o.crf) + " is out of range for " + codec.label + ": choose " +
                      std::to_string(codec.lowest) + ".." + std::to_string(codec.highest));
  bool known_preset = false;
  for (const char* const* p = codec.presets; p && *p; ++p) known_preset |= o.preset == *p;
  if (!o.preset.empty() && codec.presets && !known_preset)
    throw OutputError("unknown " + std::string(codec.presets_of) + " preset '" + o.preset + "': choose " +
                      preset_names(codec));
  if (lossless && !codec.lossless)
    throw OutputError("--quality lossless needs " + codec_labels([](const Codec& c) { return c.lossless; }) + ", not " + codec.label +
                      ": write .mp4, .mkv or .webm");
  if (lossless && o.crf >= 0) throw OutputError("--quality lossless and --crf exclude each other: give one of them");
  if (!o.preset.empty() && !codec.presets)
    notes.push_back("the preset applies to " + codec_labels([](const Codec& c) { return c.presets != nullptr; }) + " only: ignored");
  if (!has_quality && o.crf >= 0) notes.push_back(std::string(codec.label) + " has no quality setting: crf ignored");
  if (o.transparent && !carries_alpha(codec))
    throw OutputError(std::string(codec.label) +
                      " video cannot be transparent: write .webm (VP9 with alpha), .mov (ProRes 4444 with alpha) or "
                      "PNG frames such as frames/tmp_%04d.png");
  if (codec.smooth_fps && o.fps > codec.smooth_fps) {
    char shortest[32];
    std::snprintf(shortest, sizeof shortest, "%g", 1.0 / codec.smooth_fps);
    notes.push_back(std::string(codec.label) + " viewers slow down frames shorter than " + shortest + " s: use " +
                    std::to_string(codec.smooth_fps) + " fps or less");
  }
}

FormatChoice choose_format(const fs::path& final_path, const VideoOptions& o, std::vector<std::string>& notes) {
  const Container& container = container_of(final_path, o);
  const Codec& codec = find_codec(o.codec.empty() ? container.codec : o.codec);
  const AVCodec* encoder = avcodec_find_encoder_by_name(codec.encoder);
  if (!encoder)
    throw OutputError(std::string("this FFmpeg has no ") + codec.encoder + " encoder: install libavcodec-extra or choose " +
                      codec.fallback);
  const AVOutputFormat* muxer = av_guess_format(container.format, nullptr, nullptr);
  if (!muxer || avformat_query_codec(muxer, encoder->id, FF_COMPLIANCE_NORMAL) != 1)
    throw OutputError(std::string(container.extension) + " files cannot hold " + codec.label +
                      " video: choose another codec or extension");
  check_codec_options(codec, o, notes);
  return {container, codec, encoder, muxer, o.transparent || codec.always_alpha, o.quality == VideoQuality::lossless};
}
}  // namespace

/// The frame size the encoder codes (even for H.264), and the queue's length.
void VideoWriter::Impl::size_frames(const VideoOptions& o, const Codec& codec, std::vector<std::string>& notes) {
  width = o.width;
  height = o.height;
  coded_width = codec.even_size ? (o.width + 1) & ~1 : o.width;
  coded_height = codec.even_size ? (o.height + 1) & ~1 : o.height;
  if (coded_width != o.width || coded_height != o.height)
    notes.push_back(std::string(codec.label) + " needs even sizes: " + std::to_string(o.width) + "x" +
                    std::to_string(o.height) + " encoded as " + std::to_string(coded_width) + "x" +
                    std::to_string(coded_height));
  // Bounded queue: a few frames, fewer when frames are huge.
  const std::size_t frame_bytes = std::size_t(coded_width) * coded_height * 4;
  capacity = frame_bytes > (64u << 20) ? 1 : 3;
}

/// The container's context and the encoder, opened with the codec's tuning.
void VideoWriter::Impl::open_encoder(const VideoOptions& o, const FormatChoice& f) {
  check(avformat_alloc_output_context2(&format, f.muxer, nullptr, streaming ? nullptr : file->path().c_str()),
        "setting up the container", false);
  stream = avformat_new_stream(format, nullptr);
  codec = avcodec_alloc_context3(f.encoder);
  packet = av_packet_alloc();
  if (!stream || !codec || !packet) check(AVERROR(ENOMEM), "setting up the encoder", false);
  AVCodecContext* c = codec;
  c->width = coded_width;
  c->height = coded_height;
  c->time_base = AVRational{1, o.fps};  // pts = frame index
  c->framerate = AVRational{o.fps, 1};
  c->gop_size = 5 * o.fps;  // seeking stays quick; key frames, the bulk of a line-art video, stay few
  c->pix_fmt = f.alpha ? f.codec.alpha_pixels : f.codec.pixels;
  stream->time_base = c->time_base;  // a hint: the muxer may choose another in write_header
  stream->avg_frame_rate = c->framerate;
  if (c->pix_fmt != AV_PIX_FMT_PAL8) {  // the tags say what the conversion does
    c->color_range = AVCOL_RANGE_MPEG;
    c->colorspace = AVCOL_SPC_BT709;
    c->color_primaries = AVCOL_PRI_BT709;
    c->color_trc = AVCOL_TRC_BT709;
  }
  const int q = o.crf >= 0 ? o.crf : f.lossless ? 0 : f.codec.quality[static_cast<int>(o.quality)];
  AVDictionary* settings = nullptr;
  f.codec.tune({c, &settings, q, f.lossless, o.preset});
  if (o.threads > 0) c->thread_count = o.threads;
  if (format->oformat->flags & AVFMT_GLOBALHEADER) c->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
  const EncoderPriority started;
  const int opened = avcodec_open2(c, f.encoder, &settings);
  started.lower_started_since();
  av_dict_free(&settings);
  check(opened, std::string("opening the ") + f.codec.encoder + " encoder", false);
  check(avcodec_parameters_from_context(stream->codecpar, c), "setting up the stream", false);
}

/// The queue's frames, one with the worker and one being converted, and the
/// conversion the pixel format needs.
void VideoWriter::Impl::allocate_frames() {
  for (std::size_t i = 0; i < capacity + 2; ++i) {
    AVFrame* frame = av_frame_alloc();
    if (!frame) check(AVERROR(ENOMEM), "allocating a frame", false);
    frames.push_back(frame);
    frame->format = codec->pix_fmt;
    frame->width = codec->width;
    frame->height = codec->height;
    check(allocate_frame_pixels(frame), "allocating a frame", false);
    free_frames.push_back(frame);
  }
  if (codec->pix_fmt == AV_PIX_FMT_PAL8)
    palette = std::make_unique<GifPalette>();
  else if (codec->pix_fmt == AV_PIX_FMT_YUVA444P10LE)
    alpha_converter = std::make_unique<YuvaConverter>(YuvaConverter::Layout::yuva444p10, width, height);
  else if (codec->pix_fmt == AV_PIX_FMT_YUVA420P)
    alpha_converter = std::make_unique<YuvaConverter>(YuvaConverter::Layout::yuva420p, width, height);
  else
    converter = std::make_unique<Yuv420Converter>(width, height, coded_width, coded_height);
}

/// The file (or standard output) opened and the container's header written.
void VideoWriter::Impl::open_output(const VideoOptions& o, const Container& container) {
  for (const auto& [key, value] : o.metadata)
    check(av_dict_set(&format->metadata, key.c_str(), value.c_str(), 0), "setting metadata", false);
  if (streaming) {
    format->pb = open_standard_output_io();
    if (!format->pb) check(AVERROR(ENOMEM), "opening standard output", true);
  } else {
    check(avio_open(&format->pb, file->path().c_str(), AVIO_FLAG_WRITE), "opening the file", true);
  }
  AVDictionary* header = nullptr;
  if (container.movflags) av_dict_set(&header, "movflags", container.movflags, 0);
  const int written = avformat_write_header(format, &header);
  av_dict_free(&header);
  check(written, "writing the header", true);
  next_pts = o.first_frame;
}

/// The encoding thread, which lowers its own priority before the writer is
/// ready, so the threads are as they will stay from the first write.
void VideoWriter::Impl::start_worker() {
  std::promise<void> lowered;
  std::future<void> worker_ready = lowered.get_future();
  worker = std::thread([this, &lowered] {
    EncoderPriority::lower_this_thread();
    lowered.set_value();
    work();
  });
  worker_ready.wait();
}

VideoWriter::VideoWriter(const fs::path& final_path, const VideoOptions& o) {
  av_log_set_level(AV_LOG_ERROR);  // x264 and the muxers are chatty
  check_size_and_rate(o);
  const FormatChoice format = choose_format(final_path, o, notes_);
  impl_ = std::make_unique<Impl>(final_path);  // checks that the directory is writable
  impl_->size_frames(o, format.codec, notes_);
  impl_->open_encoder(o, format);
  impl_->allocate_frames();
  impl_->open_output(o, format.container);
  impl_->start_worker();
}

VideoWriter::~VideoWriter() = default;

fs::path VideoWriter::file() const { return impl_ && impl_->file ? impl_->file->final_path() : fs::path(); }

void VideoWriter::write(const std::uint8_t* argb32, int stride, const Damage* changed) {
  if (finished_) throw std::logic_error("VideoWriter::write after finish");
  Impl& m = *impl_;
  AVFrame* frame = nullptr;
  {
    std::unique_lock lock(m.mutex);
    m.changed.wait(lock, [&] { return m.queue.size() < m.capacity || !m.failure.empty(); });
    if (m.output_failed) throw StandardOutputFailed{};
    if (!m.failure.empty()) throw OutputError(m.failure);
    frame = m.free_frames.back();  // never empty: see frames
    m.free_frames.pop_back();
  }
  try {
    m.convert(argb32, stride, changed, frame);
    frame->pict_type = keyframe_next_ ? AV_PICTURE_TYPE_I : AV_PICTURE_TYPE_NONE;  // I: x264 and libvpx code a keyframe
    keyframe_next_ = false;
  } catch (...) {
    std::lock_guard lock(m.mutex);
    m.free_frames.push_back(frame);
    throw;
  }
  {
    std::lock_guard lock(m.mutex);
    m.queue.push_back(frame);
  }
  m.changed.notify_all();
  ++frames_;
}

void VideoWriter::finish() {
  if (finished_) throw std::logic_error("VideoWriter::finish called twice");
  Impl& m = *impl_;
  {
    std::lock_guard lock(m.mutex);
    m.closing = true;
  }
  m.changed.notify_all();
  if (m.worker.joinable()) m.worker.join();
  try {
    if (!m.failure.empty()) throw OutputError(m.failure);
    m.encode(nullptr);  // flush: encoders hold back frames for look-ahead
    m.check(av_write_trailer(m.format), "writing the trailer", true);
    if (m.streaming) {
      m.check(close_standard_output_io(m.format->pb), "writing", true);
    } else {
      m.check(avio_closep(&m.format->pb), "closing the file", true);
      m.file->commit();
    }
  } catch (const OutputError&) {
    if (m.output_failed) throw StandardOutputFailed{};
    throw;
  }
  finished_ = true;
}

}  // namespace vibra::render
