// FrameSink: where rendered frames go (a PNG sequence or a video file), and the video settings of the command line.
#include "render/encode/frame_sink.hpp"

#include <algorithm>
#include <thread>
#include <cmath>
#include <filesystem>

#include "render/encode/png/png_sequence.hpp"
#include "render/encode/video_writer.hpp"
#include "render/encode/y4m_stream.hpp"
#include "render/output/output_error.hpp"
#include "render/output/output_path.hpp"
#include "render/output/standard_output.hpp"

namespace vibra::render {

namespace {
VideoQuality parse_quality(const std::string& q) {
  if (q == "draft") return VideoQuality::draft;
  if (q == "medium" || q.empty()) return VideoQuality::medium;
  if (q == "high") return VideoQuality::high;
  if (q == "lossless") return VideoQuality::lossless;
  throw OutputError("--quality " + q + " is not one of draft, medium, high, lossless");
}

class VideoSink final : public FrameSink {
 public:
  VideoSink(const std::string& path, const VideoOptions& options) : path_(path), writer_(path, options) {}
  void write(const std::uint8_t* bgra, int stride, const Damage* changed) override {
    writer_.write(bgra, stride, changed);
  }
  void finish() override { writer_.finish(); }
  void start_keyframe() override { writer_.start_keyframe(); }
  std::vector<std::string> notes() const override { return writer_.notes(); }
  std::string description() const override {
    OutputTarget target;
    target.named = path_, target.file = writer_.file();
    const std::string where = path_ == VideoWriter::kStandardOutput ? standard_output_name() : target.shown();
    return where + " (" + std::to_string(writer_.frames_written()) + " frames)";
  }

 private:
  std::string path_;
  VideoWriter writer_;
};

class PngSink final : public FrameSink {
 public:
  PngSink(FramePattern pattern, int width, int height, int threads, long long first, long long count)
      : pattern_(pattern), first_(first), count_(count), writer_(std::move(pattern), width, height, threads, first) {}
  void write(const std::uint8_t* bgra, int stride, const Damage*) override { writer_.write(bgra, stride); }
  void finish() override {
    writer_.finish();
    // A whole render (not a segment) leaves exactly its own frames under the
    // pattern: an earlier run's extra frames go, but only now that the new
    // set is complete, and only those a ledger proves vibra wrote
    // (docs/reliability.md, "Frames of an earlier, longer run").
    FrameLedger ledger(pattern_.directory);
    if (first_ == 0 && writer_.frames_written() == count_) {
      earlier_ = remove_earlier_frames(pattern_, count_, ledger);
      ledger_note_ = ledger.record_whole_run(writer_.written_listing());
    } else {
      ledger_note_ = ledger.record_segment(first_, writer_.written_listing());
    }
  }
  std::string description() const override {
    std::string d = std::to_string(writer_.frames_written()) + " frames " + pattern_.name(first_).string() + " ... " +
                    pattern_.name(first_ + std::max(0LL, writer_.frames_written() - 1)).string();
    if (earlier_.removed) d += "; removed " + std::to_string(earlier_.removed) + " frames of an earlier run beyond these";
    if (earlier_.kept)
      d += "; kept " + std::to_string(earlier_.kept) +
           " files named like frames that vibra cannot prove it wrote (remove them yourself if they are old frames)";
    if (!ledger_note_.empty()) d += "; " + ledger_note_;
    return d;
  }

 private:
  FramePattern pattern_;
  long long first_, count_;
  EarlierFrames earlier_;
  std::string ledger_note_;
  PngSequenceWriter writer_;
};
class Y4mSink final : public FrameSink {
 public:
  Y4mSink(int width, int height, int fps) : stream_(width, height, fps) {}
  void write(const std::uint8_t* bgra, int stride, const Damage* changed) override { stream_.write(bgra, stride, changed); }
  void finish() override {}  // every frame went out whole when written
  std::string description() const override {
    return standard_output_name() + " (" + std::to_string(stream_.frames_written()) + " frames, y4m)";
  }

 private:
  Y4mStream stream_;
};

class TeeSink final : public FrameSink {
 public:
  explicit TeeSink(std::vector<std::unique_ptr<FrameSink>> sinks) : sinks_(std::move(sinks)) {}
  void write(const std::uint8_t* bgra, int stride, const Damage* changed) override {
    for (auto& s : sinks_) s->write(bgra, stride, changed);
  }
  void finish() override {
    for (auto& s : sinks_) s->finish();
  }
  void start_keyframe() override {
    for (auto& s : sinks_) s->start_keyframe();
  }
  std::vector<std::string> notes() const override {
    std::vector<std::string> all;
    for (const auto& s : sinks_)
      for (auto& n : s->notes())
        if (std::find(all.begin(), all.end(), n) == all.end()) all.push_back(n);
    return all;
  }
  std::string description() const override {
    std::string d;
    for (const auto& s : sinks_) d += (d.empty() ? "" : " and ") + s->description();
    return d;
  }

 private:
  std::vector<std::unique_ptr<FrameSink>> sinks_;
};
}  // namespace

std::unique_ptr<FrameSink> make_frame_sinks(const std::vector<std::string>& outputs, int width, int height, double fps,
                                            long long frame_count, const VideoSettings& settings,
                                            const std::map<std::string, std::string>& metadata, long long first_frame) {
  std::vector<std::unique_ptr<FrameSink>> sinks;
  for (const std::string& output : outputs)
    sinks.push_back(make_frame_sink(output, width, height, fps, frame_count, settings, metadata, first_frame));
  if (sinks.size() == 1) return std::move(sinks.front());
  return std::make_unique<TeeSink>(std::move(sinks));
}

bool is_video_path(const std::string& output) { return VideoWriter::is_video_path(output); }

bool is_frame_pattern(const std::string& output) {
  std::error_code ec;
  return output.find('%') != std::string::npos || std::filesystem::is_directory(output, ec) ||
         (!output.empty() && output.back() == '/');
}

void require_stream_format(const std::string& format) {
  if (format != "y4m" && format != "nut" && format != "matroska")
    throw OutputError((format.empty() ? std::string("a video goes to a stream (-o -, a pipe or a device) in a stream format")
                                      : "--format " + format + " is not a stream format") +
                      ": add --format y4m (raw frames), nut or matroska (H.264)");
}

void check_output_settings(const std::string& output, bool stream, const VideoSettings& settings) {
  if (stream) {
    require_stream_format(settings.format);
    if (settings.transparent)
      throw OutputError("--transparent cannot go to " + (output == "-" ? std::string("standard output") : "a stream (" + output + ")") +
                        ": write .webm, .mov or PNG frames such as frames/tmp_%04d.png");
    return;
  }
  if (!settings.format.empty())
    throw OutputError("--format is for a stream (-o -, a pipe or a device): a file's extension chooses its format");
  if (settings.transparent && is_video_path(output)) {
    const std::string problem = VideoWriter::alpha_problem(output, settings.codec);
    if (!problem.empty()) throw OutputError(problem);
  }
}

std::unique_ptr<FrameSink> make_frame_sink(const std::string& output, int width, int height, double fps,
                                           long long frame_count, const VideoSettings& settings,
                                           const std::map<std::string, std::string>& metadata,
                                           long long first_frame) {
  const bool stream = output == VideoWriter::kStandardOutput;
  if (stream) require_stream_format(settings.format);
  if (stream && settings.format == "y4m") return std::make_unique<Y4mSink>(width, height, static_cast<int>(std::lround(fps)));
  if (stream || is_video_path(output)) {
    VideoOptions options;
    options.width = width;
    options.height = height;
    options.fps = static_cast<int>(std::lround(fps));
    options.codec = settings.codec;
    options.quality = parse_quality(settings.quality);
    options.crf = settings.crf;
    options.preset = settings.preset;
    options.threads = settings.threads;
    options.metadata = metadata;
    options.first_frame = first_frame;
    options.transparent = settings.transparent;
    options.format = settings.format;
    return std::make_unique<VideoSink>(output, options);
  }
  const int threads = settings.threads > 0 ? settings.threads : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  return std::make_unique<PngSink>(parse_frame_pattern(output, frame_count), width, height, threads, first_frame,
                                   frame_count);
}

}  // namespace vibra::render
