// vibra concat: joins a render's segment videos into one, in order, without re-encoding.
#include "render/encode/join/video_concat.hpp"

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
}

#include <algorithm>
#include <cmath>
#include <cstring>
#include <memory>

#include "core/input/input_files.hpp"
#include "render/encode/av_error.hpp"
#include "render/encode/join/remux_files.hpp"
#include "render/output/output_error.hpp"
#include "render/output/output_path.hpp"
#include "render/output/temporary_file.hpp"

namespace fs = std::filesystem;

namespace vibra::render {

namespace {
using Input = MediaInput;

/// One segment file, opened and checked.
struct Part {
  fs::path path;
  Input input;
  AVStream* stream = nullptr;
  FrameSegment segment;
  AVRational frame_rate{0, 1};
};

std::string quoted(const fs::path& path) { return quoted_path(path); }

[[noreturn]] void refuse(const Part& part, const std::string& problem, const std::string& fix) {
  throw OutputError("cannot join " + quoted(part.path) + ": " + problem + ": " + fix);
}

Part open_part(const fs::path& path) {
  Part part;
  part.path = path;
  std::string error;
  part.input = open_media_input(path, error);
  if (!part.input) refuse(part, "it cannot be read (" + error + ")", "give segment videos made by vibra render --segment");
  AVFormatContext* c = part.input.get();
  const int found = avformat_find_stream_info(c, nullptr);
  if (found < 0) refuse(part, "it cannot be read (" + av_error(found) + ")", "render it again");
  const int video = av_find_best_stream(c, AVMEDIA_TYPE_VIDEO, -1, -1, nullptr, 0);
  if (video < 0 || c->nb_streams != 1) refuse(part, "it does not hold exactly one video stream", "give vibra's segment videos");
  part.stream = c->streams[video];
  const auto segment = FrameSegment::from_tag(container_metadata(c, "description"));
  if (!segment) refuse(part, "it is not a segment (no segment tag)", "render the parts with vibra render --segment K/N");
  part.segment = *segment;
  part.frame_rate = stream_frame_rate(part.stream);
  if (part.frame_rate.num <= 0) refuse(part, "it has no frame rate", "render it again");
  return part;
}

/// Checks that `parts` are the segments of one render, each once, none
/// missing, and sorts them in frame order.
void check_parts(std::vector<Part>& parts) {
  std::sort(parts.begin(), parts.end(), [](const Part& a, const Part& b) { return a.segment.index < b.segment.index; });
  const Part& head = parts.front();
  const FrameSegment& s = head.segment;
  for (const Part& part : parts) {
    const FrameSegment& t = part.segment;
    if (t.render != s.render)
      refuse(part, "it is from another render than " + quoted(head.path) +
                       " (other scene, parameters, size, timing or video options)",
             "join the segments of one render");
    if (t.count != s.count || t.total != s.total)
      refuse(part, "it is segment " + std::to_string(t.index) + "/" + std::to_string(t.count) + " of " +
                       std::to_string(t.total) + " frames, but " + quoted(head.path) + " is one of " +
                       std::to_string(s.count) + " segments of " + std::to_string(s.total) + " frames",
             "join the segments of one split");
    const std::string difference = differing_video_parameter(head.stream, part.stream);
    if (!difference.empty())
      refuse(part, "it has " + difference + " (unlike " + quoted(head.path) + ")",
             "render every segment with the same options");
  }
  long long expected = 0;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const FrameSegment& t = parts[i].segment;
    if (t.index < expected)
      refuse(parts[i], "it is segment " + std::to_string(t.index) + "/" + std::to_string(t.count) + ", as " +
                           quoted(parts[i - 1].path) + " is",
             "give each segment once");
    if (t.index > expected) {
      const FrameSegment missing{expected, s.count, s.total, s.render};
      throw OutputError("cannot join: segment " + std::to_string(expected) + "/" + std::to_string(s.count) +
                        " (frames " + std::to_string(missing.first()) + "-" + std::to_string(missing.end() - 1) +
                        ") is missing before " + quoted(parts[i].path) + ": render it with --segment " +
                        std::to_string(expected) + "/" + std::to_string(s.count));
    }
    expected = t.index + 1;
  }
  if (expected != s.count) {
    const FrameSegment missing{expected, s.count, s.total, s.render};
    throw OutputError("cannot join: segment " + std::to_string(expected) + "/" + std::to_string(s.count) + " (frames " +
                      std::to_string(missing.first()) + "-" + std::to_string(missing.end() - 1) +
                      ") is missing after " + quoted(parts.back().path) + ": render it with --segment " +
                      std::to_string(expected) + "/" + std::to_string(s.count));
  }
}

}  // namespace

std::string read_video_description(const fs::path& video) {
  av_log_set_level(AV_LOG_QUIET);  // an unreadable file simply has no description
  std::string error;
  std::error_code ec;
  if (!fs::is_regular_file(video, ec)) return "";
  const Input input = open_media_input(video, error);
  return input ? container_metadata(input.get(), "description") : "";
}

std::optional<FrameSegment> read_segment_tag(const fs::path& video) {
  return FrameSegment::from_tag(read_video_description(video));
}

namespace {
/// The output's one stream, a copy of the first part's, and its header written.
AVStream* start_output(MuxedOutput& out, const std::vector<Part>& parts, const fs::path& output) {
  const AVOutputFormat* muxer = av_guess_format(nullptr, output.c_str(), nullptr);
  const AVCodecParameters* codec = parts.front().stream->codecpar;
  if (!muxer || avformat_query_codec(muxer, codec->codec_id, FF_COMPLIANCE_NORMAL) != 1)
    throw OutputError("-o " + quoted(output) + " cannot hold " + avcodec_get_name(codec->codec_id) +
                      " video: name it like the parts (" + parts.front().path.extension().string() + ")");
  out.open(muxer);
  AVStream* out_stream = avformat_new_stream(out.format, nullptr);
  if (!out_stream) out.check(AVERROR(ENOMEM), "setting up");
  out.check(avcodec_parameters_copy(out_stream->codecpar, codec), "setting up");
  out_stream->codecpar->codec_tag = 0;  // the output container chooses its own
  out_stream->time_base = parts.front().stream->time_base;
  out_stream->avg_frame_rate = parts.front().frame_rate;
  for (const char* key : {"title", "comment"})
    if (const std::string value = container_metadata(parts.front().input.get(), key); !value.empty())
      av_dict_set(&out.format->metadata, key, value.c_str(), 0);
  out.write_header();
  return out_stream;
}

/// Copies one part's packets into the output, checking that it holds
/// exactly the frames its tag names, once each, after the previous part's.
/// Returns how many it copied.
long long copy_part(Part& part, MuxedOutput& out, AVStream* out_stream, AVPacket* packet, std::int64_t& last_dts) {
  const FrameSegment& s = part.segment;
  std::vector<bool> seen(static_cast<std::size_t>(s.frames()), false);
  const AVRational frame_base = av_inv_q(part.frame_rate);
  // Matroska stores no decoding timestamps: its demuxer guesses them, but
  // not for a file's first packets. With B-frames a guess-less packet at a
  // seam would break the order, so all of them go, and the muxer derives
  // each from the presentation timestamps, as for any stream without them.
  const bool guessed_dts = std::strstr(part.input->iformat->name, "matroska") != nullptr;
  long long copied = 0;
  for (;;) {
    const int read = av_read_frame(part.input.get(), packet);
    if (read == AVERROR_EOF) break;
    if (read < 0) refuse(part, "reading it failed (" + av_error(read) + ")", "render it again");
    if (packet->pts == AV_NOPTS_VALUE) refuse(part, "a packet has no timestamp", "render it again");
    const long long frame = av_rescale_q_rnd(packet->pts, part.stream->time_base, frame_base,
                                             static_cast<AVRounding>(AV_ROUND_NEAR_INF | AV_ROUND_PASS_MINMAX));
    if (frame < s.first() || frame >= s.end() || seen[frame - s.first()])
      refuse(part, "it holds frame " + std::to_string(frame) + ", not only frames " + std::to_string(s.first()) + "-" +
                       std::to_string(s.end() - 1) + " once each as its tag says",
             "render it again");
    seen[frame - s.first()] = true;
    if (guessed_dts) packet->dts = AV_NOPTS_VALUE;
    av_packet_rescale_ts(packet, part.stream->time_base, out_stream->time_base);
    if (packet->dts != AV_NOPTS_VALUE) {
      if (last_dts != AV_NOPTS_VALUE && packet->dts <= last_dts)
        refuse(part, "its decoding timestamps overlap the previous part's", "render every segment with the same options");
      last_dts = packet->dts;
    }
    packet->stream_index = out_stream->index;
    packet->pos = -1;
    out.check(av_interleaved_write_frame(out.format, packet), "writing a frame");  // takes the packet's data
    ++copied;
  }
  const auto held = std::count(seen.begin(), seen.end(), true);
  if (held != s.frames())
    refuse(part, "it holds " + std::to_string(held) + " of the " + std::to_string(s.frames()) + " frames its tag names",
           "render it again");
  return copied;
}
}  // namespace

ConcatSummary concat_segments(const std::vector<fs::path>& paths, const fs::path& output) {
  av_log_set_level(AV_LOG_QUIET);  // every failure is reported in our words, with FFmpeg's reason
  if (paths.empty()) throw OutputError("concat needs the segment videos to join: give PART... -o OUT");
  for (const fs::path& path : paths) note_input_file(path, "a part to join");
  const fs::path file = resolve_output(output.string()).file;  // not a part, nor a folder
  std::vector<Part> parts;
  for (const fs::path& path : paths) parts.push_back(open_part(path));
  check_parts(parts);
  MuxedOutput out(file);
  AVStream* out_stream = start_output(out, parts, output);
  std::unique_ptr<AVPacket, void (*)(AVPacket*)> packet(av_packet_alloc(), [](AVPacket* p) { av_packet_free(&p); });
  if (!packet) out.check(AVERROR(ENOMEM), "allocating a packet");
  std::int64_t last_dts = AV_NOPTS_VALUE;
  ConcatSummary summary{0, parts.size()};
  for (Part& part : parts) summary.frames += copy_part(part, out, out_stream, packet.get(), last_dts);
  out.finish_and_commit();
  return summary;
}

}  // namespace vibra::render
