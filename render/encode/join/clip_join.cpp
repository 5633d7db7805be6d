// Joins a lecture's clips into one video with chapters and subtitle streams, copying packets without re-encoding.
#include "render/encode/join/clip_join.hpp"

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
}

#include <cmath>
#include <cstring>
#include <memory>
#include <optional>

#include "render/encode/audio/audio_track.hpp"
#include "render/encode/av_error.hpp"
#include "render/output/stop_signal.hpp"
#include "render/encode/join/remux_files.hpp"
#include "render/output/output_error.hpp"
#include "render/output/output_path.hpp"

namespace fs = std::filesystem;

namespace vibra::render {

namespace {
struct Clip {
  fs::path path;
  MediaInput input;
  AVStream* stream = nullptr;
};

[[noreturn]] void refuse(const fs::path& clip, const std::string& problem) {
  throw OutputError("cannot join " + quoted_path(clip) + ": " + problem + ": render it again");
}

Clip open_clip(const fs::path& path) {
  Clip clip{path, nullptr, nullptr};
  std::string error;
  clip.input = open_media_input(path, error);
  if (!clip.input) refuse(path, "it cannot be read (" + error + ")");
  const int found = avformat_find_stream_info(clip.input.get(), nullptr);
  if (found < 0) refuse(path, "it cannot be read (" + av_error(found) + ")");
  if (clip.input->nb_streams != 1 || clip.input->streams[0]->codecpar->codec_type != AVMEDIA_TYPE_VIDEO)
    refuse(path, "it does not hold exactly one video stream");
  clip.stream = clip.input->streams[0];
  return clip;
}

/// The ASS header FFmpeg's text subtitle encoders parse their styles from.
constexpr const char* kAssHeader =
    "[Script Info]\r\nScriptType: v4.00+\r\nPlayResX: 384\r\nPlayResY: 288\r\n\r\n[V4+ Styles]\r\n"
    "Format: Name, Fontname, Fontsize, PrimaryColour, SecondaryColour, OutlineColour, BackColour, Bold, Italic, "
    "Underline, StrikeOut, ScaleX, ScaleY, Spacing, Angle, BorderStyle, Outline, Shadow, Alignment, MarginL, MarginR, "
    "MarginV, Encoding\r\nStyle: Default,Arial,16,&Hffffff,&Hffffff,&H0,&H0,0,0,0,0,100,100,0,0,1,1,0,2,10,10,10,0\r\n"
    "\r\n[Events]\r\nFormat: Layer, Start, End, Style, Name, MarginL, MarginR, MarginV, Effect, Text\r\n";

/// A cue's text as an ASS dialogue's: lines joined by \N, no override braces.
std::string ass_text(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '\n') out += "\\N";
    else if (c != '{' && c != '}' && c != '\r') out += c;
  }
  return out;
}

struct CodecContextFree {
  void operator()(AVCodecContext* c) const { avcodec_free_context(&c); }
};

/// The subtitle track: an encoder (mov_text or webvtt) and its stream.
struct SubtitleTrack {
  std::unique_ptr<AVCodecContext, CodecContextFree> codec;
  AVStream* stream = nullptr;

  SubtitleTrack(MuxedOutput& out, bool mp4) {
    const AVCodec* encoder = avcodec_find_encoder(mp4 ? AV_CODEC_ID_MOV_TEXT : AV_CODEC_ID_WEBVTT);
    if (!encoder) throw OutputError(std::string("this FFmpeg has no ") + (mp4 ? "mov_text" : "WebVTT") +
                                    " subtitle encoder: install libavcodec-extra, or write .html");
    codec.reset(avcodec_alloc_context3(encoder));
    if (!codec) out.check(AVERROR(ENOMEM), "setting up the subtitles");
    codec->time_base = AVRational{1, 1000};
    codec->subtitle_header = reinterpret_cast<std::uint8_t*>(av_strdup(kAssHeader));
    codec->subtitle_header_size = int(std::strlen(kAssHeader));
    if (out.format->oformat->flags & AVFMT_GLOBALHEADER) codec->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
    out.check(avcodec_open2(codec.get(), encoder, nullptr), "opening the subtitle encoder");
    stream = avformat_new_stream(out.format, nullptr);
    if (!stream) out.check(AVERROR(ENOMEM), "setting up the subtitles");
    out.check(avcodec_parameters_from_context(stream->codecpar, codec.get()), "setting up the subtitles");
    stream->time_base = codec->time_base;
    av_dict_set(&stream->metadata, "language", "eng", 0);
    av_dict_set(&stream->metadata, "title", "Notes", 0);
  }

  void write(MuxedOutput& out, const SubtitleCue& cue, AVPacket* packet) {
    std::string line = "0,0,Default,,0,0,0,," + ass_text(cue.text);
    AVSubtitleRect rect{};
    rect.type = SUBTITLE_ASS;
    rect.ass = line.data();
    AVSubtitleRect* rects[] = {&rect};
    AVSubtitle subtitle{};
    subtitle.num_rects = 1;
    subtitle.rects = rects;
    const long long start = std::llround(cue.start * 1000), end = std::llround(cue.end * 1000);
    subtitle.start_display_time = 0;
    subtitle.end_display_time = static_cast<std::uint32_t>(end - start);
    subtitle.pts = av_rescale(start, AV_TIME_BASE, 1000);
    std::vector<std::uint8_t> buffer(line.size() * 4 + 1024);
    const int size = avcodec_encode_subtitle(codec.get(), buffer.data(), int(buffer.size()), &subtitle);
    out.check(size, "encoding a subtitle");
    out.check(av_new_packet(packet, size), "encoding a subtitle");
    std::memcpy(packet->data, buffer.data(), std::size_t(size));
    packet->pts = packet->dts = start;
    packet->duration = end - start;
    av_packet_rescale_ts(packet, codec->time_base, stream->time_base);
    packet->stream_index = stream->index;
    out.check(av_interleaved_write_frame(out.format, packet), "writing a subtitle");
  }
};

/// How far the sound runs ahead of the frames in the file: the muxer
/// interleaves within it, and players buffer it.
constexpr double kSoundLead = 0.5;  // seconds

void add_chapters(MuxedOutput& out, const std::vector<VideoChapter>& chapters, int fps) {
  if (chapters.empty()) return;
  auto** list = static_cast<AVChapter**>(av_calloc(chapters.size(), sizeof(AVChapter*)));
  if (!list) out.check(AVERROR(ENOMEM), "adding chapters");
  out.format->chapters = list;
  for (std::size_t i = 0; i < chapters.size(); ++i) {
    auto* chapter = static_cast<AVChapter*>(av_mallocz(sizeof(AVChapter)));
    if (!chapter) out.check(AVERROR(ENOMEM), "adding chapters");
    list[i] = chapter;
    out.format->nb_chapters = unsigned(i + 1);  // freed with the context from here on
    chapter->id = std::int64_t(i + 1);
    chapter->time_base = AVRational{1, fps};
    chapter->start = chapters[i].first_frame;
    chapter->end = chapters[i].end_frame;
    out.check(av_dict_set(&chapter->metadata, "title", chapters[i].title.c_str(), 0), "adding chapters");
  }
}
}  // namespace

void join_clips(const std::vector<ClipFile>& files, const fs::path& output, int fps,
                const std::vector<VideoChapter>& chapters, const std::vector<SubtitleCue>& cues,
                const std::map<std::string, std::string>& metadata, const AudioClip* sound) {
  av_log_set_level(AV_LOG_QUIET);  // every failure is reported in our words, with FFmpeg's reason
  if (files.empty()) throw OutputError("a lecture needs at least one shot to join");
  std::vector<Clip> clips;
  for (const ClipFile& file : files) clips.push_back(open_clip(file.path));
  for (const Clip& clip : clips)
    if (const std::string difference = differing_video_parameter(clips.front().stream, clip.stream); !difference.empty())
      refuse(clip.path, "it has " + difference + " (unlike " + quoted_path(clips.front().path) + ")");

  const AVOutputFormat* muxer = av_guess_format(nullptr, output.c_str(), nullptr);
  const AVCodecParameters* codec = clips.front().stream->codecpar;
  if (!muxer || avformat_query_codec(muxer, codec->codec_id, FF_COMPLIANCE_NORMAL) != 1)
    throw OutputError("-o " + quoted_path(output) + " cannot hold " + avcodec_get_name(codec->codec_id) + " video");
  MuxedOutput out(output);
  out.open(muxer);
  AVStream* video = avformat_new_stream(out.format, nullptr);
  if (!video) out.check(AVERROR(ENOMEM), "setting up");
  out.check(avcodec_parameters_copy(video->codecpar, codec), "setting up");
  video->codecpar->codec_tag = 0;  // the output container chooses its own
  video->time_base = clips.front().stream->time_base;
  video->avg_frame_rate = AVRational{fps, 1};
  std::optional<SubtitleTrack> subtitles;
  if (!cues.empty()) subtitles.emplace(out, std::strcmp(muxer->name, "mp4") == 0);
  std::optional<AudioTrack> audio;
  if (sound) audio.emplace(out, *sound, std::strcmp(muxer->name, "mp4") == 0);
  add_chapters(out, chapters, fps);
  for (const auto& [key, value] : metadata) av_dict_set(&out.format->metadata, key.c_str(), value.c_str(), 0);
  out.write_header();

  std::unique_ptr<AVPacket, void (*)(AVPacket*)> packet(av_packet_alloc(), [](AVPacket* p) { av_packet_free(&p); });
  if (!packet) out.check(AVERROR(ENOMEM), "allocating a packet");
  const AVRational frame_base{1, fps};
  long long offset = 0;  // frames before this clip
  std::size_t next_cue = 0;
  for (std::size_t i = 0; i < clips.size(); ++i) {
    Clip& clip = clips[i];
    // The cues that start before this clip ends go first (the muxer interleaves by time).
    const long long expected = files[i].frames;
    const double clip_end = double(offset + expected) / fps;
    for (; subtitles && next_cue < cues.size() && (cues[next_cue].start < clip_end || i + 1 == clips.size()); ++next_cue)
      subtitles->write(out, cues[next_cue], packet.get());
    const bool guessed_dts = std::strstr(clip.input->iformat->name, "matroska") != nullptr;  // as in concat
    long long frames = 0;
    for (;;) {
      const int read = av_read_frame(clip.input.get(), packet.get());
      if (read == AVERROR_EOF) break;
      if (read < 0) refuse(clip.path, "reading it failed (" + av_error(read) + ")");
      if (packet->pts == AV_NOPTS_VALUE) refuse(clip.path, "a packet has no timestamp");
      const std::int64_t shift = av_rescale_q(offset, frame_base, clip.stream->time_base);
      packet->pts += shift;
      packet->dts = guessed_dts || packet->dts == AV_NOPTS_VALUE ? AV_NOPTS_VALUE : packet->dts + shift;
      av_packet_rescale_ts(packet.get(), clip.stream->time_base, video->time_base);
      packet->stream_index = video->index;
      packet->pos = -1;
      const double shown = double(packet->pts) * av_q2d(video->time_base);  // in the joined video; the write takes the packet
      out.check(av_interleaved_write_frame(out.format, packet.get()), "writing a frame");
      if (audio) audio->write_until(shown + kSoundLead);
      if ((++frames & 0xff) == 0) throw_if_stop_requested();
    }
    if (frames != expected)
      refuse(clip.path, "it holds " + std::to_string(frames) + " frames, not the " + std::to_string(expected) +
                            (files.size() == 1 ? " of the lecture" : " of its shot"));
    offset += frames;
  }
  if (audio) audio->finish();
  out.finish_and_commit();
}

}  // namespace vibra::render
