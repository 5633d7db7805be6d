// AudioTrack: a lecture's sound encoded as a stream of a muxed file (AAC in MP4, Opus in WebM), written in step with its video.
#include "render/encode/audio/audio_track.hpp"

extern "C" {
#include <libavutil/channel_layout.h>
}

#include <algorithm>
#include <cstring>

#include "render/output/output_error.hpp"

namespace vibra::render {

namespace {
/// The codec per container, its bit rate for mono speech, and an encoder
/// option. FFmpeg's AAC coder "fast" took half the CPU of its default
/// "twoloop" on the narrated example's 24 s of speech (0.09 s against 0.21 s),
/// which is most of narration's cost to a render.
struct AudioCodec {
  const char* encoder;
  const char* label;
  int bit_rate;
  const char *option, *value;  ///< nullptr: none
};
constexpr AudioCodec kMp4Audio = {"aac", "AAC", 96'000, "aac_coder", "fast"};
constexpr AudioCodec kWebmAudio = {"libopus", "Opus", 64'000, nullptr, nullptr};  // libopus's defaults

/// The encoder's float format: planar or packed is the same for one channel.
AVSampleFormat float_format(const AVCodec* encoder) {
  for (const AVSampleFormat* f = encoder->sample_fmts; f && *f != AV_SAMPLE_FMT_NONE; ++f)
    if (*f == AV_SAMPLE_FMT_FLTP || *f == AV_SAMPLE_FMT_FLT) return *f;
  return AV_SAMPLE_FMT_NONE;
}
}  // namespace

AudioTrack::AudioTrack(MuxedOutput& out, const AudioClip& sound, bool mp4) : out_(out), sound_(sound) {
  const AudioCodec& kind = mp4 ? kMp4Audio : kWebmAudio;
  const AVCodec* encoder = avcodec_find_encoder_by_name(kind.encoder);
  if (!encoder || float_format(encoder) == AV_SAMPLE_FMT_NONE)
    throw OutputError(std::string("this FFmpeg has no ") + kind.label + " encoder (" + kind.encoder +
                      "): install Debian's libavcodec, or add --mute");
  codec_ = avcodec_alloc_context3(encoder);
  frame_ = av_frame_alloc();
  packet_ = av_packet_alloc();
  if (!codec_ || !frame_ || !packet_) out.check(AVERROR(ENOMEM), "setting up the sound");
  codec_->sample_fmt = float_format(encoder);
  codec_->sample_rate = AudioClip::kRate;
  av_channel_layout_default(&codec_->ch_layout, 1);
  codec_->bit_rate = kind.bit_rate;
  codec_->time_base = AVRational{1, AudioClip::kRate};
  if (out.format->oformat->flags & AVFMT_GLOBALHEADER) codec_->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
  AVDictionary* options = nullptr;
  if (kind.option) av_dict_set(&options, kind.option, kind.value, 0);
  const int opened = avcodec_open2(codec_, encoder, &options);
  av_dict_free(&options);
  out.check(opened, std::string("opening the ") + kind.label + " encoder");
  stream_ = avformat_new_stream(out.format, nullptr);
  if (!stream_) out.check(AVERROR(ENOMEM), "setting up the sound");
  out.check(avcodec_parameters_from_context(stream_->codecpar, codec_), "setting up the sound");
  stream_->time_base = codec_->time_base;
  av_dict_set(&stream_->metadata, "language", "eng", 0);
  frame_->format = codec_->sample_fmt;
  frame_->nb_samples = codec_->frame_size;
  frame_->sample_rate = AudioClip::kRate;
  out.check(av_channel_layout_copy(&frame_->ch_layout, &codec_->ch_layout), "setting up the sound");
  out.check(av_frame_get_buffer(frame_, 0), "setting up the sound");
}

AudioTrack::~AudioTrack() {
  av_packet_free(&packet_);
  av_frame_free(&frame_);
  avcodec_free_context(&codec_);
}

void AudioTrack::encode(const AVFrame* frame) {
  out_.check(avcodec_send_frame(codec_, frame), "encoding the sound");
  for (;;) {
    const int got = avcodec_receive_packet(codec_, packet_);
    if (got == AVERROR(EAGAIN) || got == AVERROR_EOF) return;
    out_.check(got, "encoding the sound");
    av_packet_rescale_ts(packet_, codec_->time_base, stream_->time_base);
    packet_->stream_index = stream_->index;
    out_.check(av_interleaved_write_frame(out_.format, packet_), "writing the sound");
  }
}

void AudioTrack::write_until(double seconds) {
  const std::size_t size = std::size_t(codec_->frame_size);
  const std::size_t end = std::size_t(std::max(0.0, seconds) * AudioClip::kRate);
  for (; next_ < end && next_ < sound_.samples.size(); next_ += size) {  // whole frames: the sound's length bounds it
    out_.check(av_frame_make_writable(frame_), "encoding the sound");
    auto* data = reinterpret_cast<float*>(frame_->data[0]);
    const std::size_t count = std::min(size, sound_.samples.size() - next_);
    std::memcpy(data, sound_.samples.data() + next_, count * sizeof(float));
    std::fill(data + count, data + size, 0.0f);  // the last frame: silence after the sound
    frame_->pts = std::int64_t(next_);
    encode(frame_);
  }
}

void AudioTrack::finish() {
  write_until(sound_.seconds() + 1);
  encode(nullptr);
}

}  // namespace vibra::render
