// Speech from flite and recorded takes, made in process through a libavfilter graph into 48 kHz mono clips.
#include "render/encode/audio/audio_source.hpp"

extern "C" {
#include <libavfilter/avfilter.h>
#include <libavfilter/buffersink.h>
#include <libavutil/frame.h>
#include <libavutil/log.h>
#include <libavutil/opt.h>
}

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <memory>
#include <utility>

#include "core/error.hpp"
#include "render/encode/av_error.hpp"
#include "render/encode/audio/loudness.hpp"
#include "render/output/stop_signal.hpp"

namespace vibra::render {

namespace {
constexpr double kLongestClip = 3600;  // seconds: a shot's longest
/// flite speaks a text in one call, deaf to Ctrl-C: a sentence's longest (about a minute of speech).
constexpr std::size_t kLongestSentence = 1000;

struct GraphFree {
  void operator()(AVFilterGraph* g) const { avfilter_graph_free(&g); }
};
struct FrameFree {
  void operator()(AVFrame* f) const { av_frame_free(&f); }
};

/// The graph's source (`source` with `options`, set unescaped, so any text
/// or file name goes through as it is), then 48 kHz mono float samples.
/// Returns FFmpeg's error code for a source that does not start.
int build_graph(AVFilterGraph* graph, const char* source, const std::vector<std::pair<std::string, std::string>>& options,
                AVFilterContext*& sink) {
  const AVFilter* filter = avfilter_get_by_name(source);
  if (!filter) return AVERROR_FILTER_NOT_FOUND;
  AVFilterContext* start = avfilter_graph_alloc_filter(graph, filter, "source");
  if (!start) return AVERROR(ENOMEM);
  for (const auto& [key, value] : options)
    if (const int set = av_opt_set(start, key.c_str(), value.c_str(), AV_OPT_SEARCH_CHILDREN); set < 0) return set;
  if (const int started = avfilter_init_str(start, nullptr); started < 0) return started;
  AVFilterContext *resample = nullptr, *format = nullptr;
  int code = avfilter_graph_create_filter(&resample, avfilter_get_by_name("aresample"), "resample", "48000", nullptr, graph);
  if (code >= 0)
    code = avfilter_graph_create_filter(&format, avfilter_get_by_name("aformat"), "format",
                                        "sample_fmts=flt:sample_rates=48000:channel_layouts=mono", nullptr, graph);
  if (code >= 0) code = avfilter_graph_create_filter(&sink, avfilter_get_by_name("abuffersink"), "sink", nullptr, nullptr, graph);
  if (code >= 0) code = avfilter_link(start, 0, resample, 0);
  if (code >= 0) code = avfilter_link(resample, 0, format, 0);
  if (code >= 0) code = avfilter_link(format, 0, sink, 0);
  return code >= 0 ? avfilter_graph_config(graph, nullptr) : code;
}

/// Pulls the graph's samples; `what` names the source in messages. At most kLongestClip.
AudioClip pull_samples(AVFilterContext* sink, const std::string& what) {
  AudioClip clip;
  std::unique_ptr<AVFrame, FrameFree> frame(av_frame_alloc());
  if (!frame) throw std::bad_alloc();
  for (;;) {
    throw_if_stop_requested();
    const int got = av_buffersink_get_frame(sink, frame.get());
    if (got == AVERROR_EOF) break;
    if (got < 0) throw UsageError(what + " cannot be read (" + av_error(got) + ")");
    const auto* data = reinterpret_cast<const float*>(frame->data[0]);
    clip.samples.insert(clip.samples.end(), data, data + frame->nb_samples);
    av_frame_unref(frame.get());
    if (clip.seconds() > kLongestClip) throw UsageError(what + " lasts more than an hour: split it over shots");
  }
  return clip;
}

AudioClip run_graph(const char* source, const std::vector<std::pair<std::string, std::string>>& options,
                    const std::string& what) {
  av_log_set_level(AV_LOG_QUIET);  // failures are told in our words, with FFmpeg's reason
  std::unique_ptr<AVFilterGraph, GraphFree> graph(avfilter_graph_alloc());
  if (!graph) throw std::bad_alloc();
  graph->nb_threads = 1;  // the encoders have the cores
  AVFilterContext* sink = nullptr;
  const int built = build_graph(graph.get(), source, options, sink);
  if (built == AVERROR_FILTER_NOT_FOUND)
    throw UsageError(std::string("this FFmpeg has no '") + source + "' filter: install Debian's libavfilter (built with libflite)");
  if (built < 0) throw UsageError(what + " cannot be read (" + av_error(built) + ")");
  return pull_samples(sink, what);
}

std::string short_text(const std::string& text) { return text.size() > 40 ? text.substr(0, 37) + "..." : text; }
}  // namespace

const std::vector<std::string>& speech_voices() {
  static const std::vector<std::string> voices = {"slt", "kal", "kal16", "awb", "rms"};
  return voices;
}

std::string voice_problem(const std::string& voice) {
  const auto& voices = speech_voices();
  if (std::find(voices.begin(), voices.end(), voice) != voices.end()) return "";
  std::string list;
  for (const auto& v : voices) list += (list.empty() ? "" : ", ") + v;
  return "unknown voice '" + short_text(voice) + "': flite speaks " + list + " (slt, the default, is the clearest)";
}

AudioClip speak(const std::string& text, const std::string& voice) {
  if (const std::string problem = voice_problem(voice); !problem.empty()) throw UsageError(problem);
  if (text.size() > kLongestSentence)
    throw UsageError("a sentence of " + std::to_string(text.size()) + " characters is more than flite speaks at once (" +
                     std::to_string(kLongestSentence) + "): break it with full stops");
  if (std::none_of(text.begin(), text.end(), [](unsigned char c) { return std::isalnum(c); }))
    throw UsageError("flite cannot speak \"" + short_text(text) + "\": it has no words (flite reads English letters and digits)");
  AudioClip clip = run_graph("flite", {{"text", text}, {"voice", voice}}, "flite's speech of \"" + short_text(text) + "\"");
  if (!std::isfinite(integrated_loudness(clip)))
    throw UsageError("flite speaks nothing of \"" + short_text(text) + "\": say words, e.g. say = \"Drag takes energy out\"");
  normalize_loudness(clip);
  return clip;
}

AudioClip read_take(const std::filesystem::path& file) {
  const std::string what = "the recording '" + file.string() + "'";
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec))
    throw UsageError("no recording '" + file.string() + "': record it, or give a WAV, FLAC, MP3 or Opus file that is there");
  AudioClip clip = run_graph("amovie", {{"filename", file.string()}}, what);
  if (!std::isfinite(integrated_loudness(clip)))
    throw UsageError(what + " is silent: record the take again, or speak the shot with say = \"...\"");
  return clip;
}

}  // namespace vibra::render
