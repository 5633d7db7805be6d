// The tables of video codecs and containers, and each codec's tuning of its encoder.
#include "render/encode/video_formats.hpp"

#include <algorithm>
#include <cctype>
#include <thread>
#include <vector>

#include "render/output/output_error.hpp"
#include "render/output/output_path.hpp"

namespace vibra::render {

namespace {
constexpr const char* kX264Presets[] = {"ultrafast", "superfast", "veryfast", "faster", "fast", "medium",
                                        "slow",      "slower",    "veryslow", "placebo",  nullptr};

void tune_h264(const EncoderSetup& e) {
  // The default, measured on the pendulum diagram at 1280x720 (encoder
  // alone, 2 threads, crf 23, 300 frames; PSNR and SSIM against the source):
  //   medium                          2.30 s CPU  202 KiB  52.98 dB  0.99969
  //   veryfast                        1.50 s      209 KiB  51.08 dB  0.99952
  //   veryfast, no B-frames, me dia   1.13 s      230 KiB  51.38 dB  0.99954
  //     + subme 1                     1.05 s      241 KiB  51.29 dB  0.99951
  //     + subme 1, 4x4 transforms     1.06 s      239 KiB  51.34 dB  0.99953  <- default
  //     + subme 0, 4x4 transforms     0.94 s      269 KiB  51.25 dB  0.99952
  // B-frames buy little where most of the picture stands still, the
  // diamond search finds a diagram's small motions as well as hex, one
  // sub-pixel pass is enough for them, and the sharp edges of line art code
  // no worse in 4x4 transforms than 8x8 (on the diagram with plot as well).
  // tune animation gave the same SSIM per byte as no tune, so none is set.
  // A --preset given by the user is x264's own preset, untouched.
  av_dict_set(e.options, "preset", e.preset.empty() ? "veryfast" : e.preset.c_str(), 0);
  if (e.preset.empty()) av_dict_set(e.options, "x264-params", "bframes=0:me=dia:subme=1:8x8dct=0", 0);
  // A ceiling: x264 signals the lowest profile its tools need (Main for
  // the default, High from superfast up, Constrained Baseline for ultrafast).
  // Lossless coding (qp 0) is High 4:4:4 Predictive's alone, even in 4:2:0.
  av_dict_set(e.options, "profile", e.lossless ? "high444" : "high", 0);
  av_dict_set(e.options, e.lossless ? "qp" : "crf", std::to_string(e.quality).c_str(), 0);
  // One frame thread per core, not x264's own 1.5 per core: the drawing
  // thread needs a share of the cores too, and on two cores the example
  // lecture took 1637 ms with two threads against 1721 ms with x264's
  // choice (nine alternating rounds); x264 alone is no slower either.
  e.context->thread_count = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

void tune_vp9(const EncoderSetup& e) {
  av_dict_set(e.options, e.lossless ? "lossless" : "crf", e.lossless ? "1" : std::to_string(e.quality).c_str(), 0);
  e.context->bit_rate = 0;  // with crf: constant quality
  av_dict_set(e.options, "row-mt", "1", 0);
  av_dict_set(e.options, "deadline", "realtime", 0);
  av_dict_set(e.options, "cpu-used", "8", 0);
  e.context->thread_count = 2;
}

void tune_vp8(const EncoderSetup& e) {
  av_dict_set(e.options, "crf", std::to_string(e.quality).c_str(), 0);
  e.context->bit_rate = 4'000'000;  // VP8's crf is constrained quality: it needs a cap
  av_dict_set(e.options, "deadline", "realtime", 0);
  av_dict_set(e.options, "cpu-used", "8", 0);
  e.context->thread_count = 1;  // libvpx's VP8 threads busy-wait: on two cores one thread is faster
}

void tune_prores(const EncoderSetup& e) {
  av_dict_set(e.options, "profile", "4444", 0);
  av_dict_set(e.options, "vendor", "apl0", 0);  // as Apple's encoder tags it: some editors look for it
  e.context->thread_count = 0;  // one slice thread per core: ProRes costs about 0.12 s of CPU per 720p frame
}

/// Theora and FLV1: a fixed quantizer.
void tune_quantizer(const EncoderSetup& e) {
  e.context->flags |= AV_CODEC_FLAG_QSCALE;
  e.context->global_quality = FF_QP2LAMBDA * e.quality;
}

void tune_nothing(const EncoderSetup&) {}

constexpr AVPixelFormat kNoAlpha = AV_PIX_FMT_NONE;

/// Quality presets {draft, medium, high}:
///   h264    crf 28 / 23 / 18  (x264, 0..51, lower is better; 23 is x264's default)
///   vp9     crf 40 / 32 / 24  (0..63, constant quality: crf with b:v 0)
///   vp8     crf 20 / 10 / 4   (4..63, constrained quality under a 4 Mb/s cap)
///   theora  q    5 /  7 / 9   (0..10, higher is better)
///   flv     q   10 /  5 / 2   (quantizer 2..31, lower is better)
///   gif     fixed palette, no quality setting
///   raw     YUV 4:2:0 as it goes to the encoders, no quality setting
/// Lossless (h264 and vp9 only): x264 at qp 0, VP9 with lossless=1; both
/// decode to exactly the YUV 4:2:0 frames they were given.
constexpr Codec kCodecs[] = {
    // name, label, encoder, quality presets, crf range, pixels, with alpha, always alpha, even size, lossless, presets (whose), smooth fps, fallback, tuning
    {"h264", "H.264", "libx264", {28, 23, 18}, 0, 51, AV_PIX_FMT_YUV420P, kNoAlpha, false, true, true, kX264Presets, "x264", 0, ".webm", tune_h264},
    {"vp9", "VP9", "libvpx-vp9", {40, 32, 24}, 0, 63, AV_PIX_FMT_YUV420P, AV_PIX_FMT_YUVA420P, false, false, true, nullptr, "", 0, ".mp4", tune_vp9},
    {"vp8", "VP8", "libvpx", {20, 10, 4}, 4, 63, AV_PIX_FMT_YUV420P, kNoAlpha, false, false, false, nullptr, "", 0, ".mp4", tune_vp8},
    {"theora", "Theora", "libtheora", {5, 7, 9}, 0, 10, AV_PIX_FMT_YUV420P, kNoAlpha, false, false, false, nullptr, "", 0, ".mp4", tune_quantizer},
    {"flv", "FLV1", "flv", {10, 5, 2}, 2, 31, AV_PIX_FMT_YUV420P, kNoAlpha, false, false, false, nullptr, "", 0, ".mp4", tune_quantizer},
    {"gif", "GIF", "gif", {0, 0, 0}, 0, 0, AV_PIX_FMT_PAL8, kNoAlpha, false, false, false, nullptr, "", 50, ".mp4", tune_nothing},
    {"raw", "raw YUV 4:2:0", "rawvideo", {0, 0, 0}, 0, 0, AV_PIX_FMT_YUV420P, kNoAlpha, false, false, false, nullptr, "", 0, ".mp4", tune_nothing},
    {"prores", "ProRes 4444", "prores_ks", {0, 0, 0}, 0, 0, AV_PIX_FMT_YUVA444P10LE, AV_PIX_FMT_YUVA444P10LE, true, false, false, nullptr, "", 0, ".mp4", tune_prores},
};

constexpr Container kContainers[] = {
    {".mp4", "mp4", "h264", "+faststart", true},  // index first: browsers play while loading
    {".mkv", "matroska", "h264", nullptr, true},
    {".webm", "webm", "vp9", nullptr, true},
    {".ogv", "ogg", "theora", nullptr, true},
    {".gif", "gif", "gif", nullptr, false},
    {".flv", "flv", "flv", nullptr, true},
    {".yuv", "rawvideo", "raw", nullptr, false},  // for other encoders: ffmpeg -f rawvideo -pix_fmt yuv420p -s WxH -r FPS -i x.yuv
    {".mov", "mov", "prores", nullptr, true},     // ProRes 4444 with alpha, for video editors
    {".nut", "nut", "h264", nullptr, true},       // FFmpeg's own container, good for pipes
};

/// "a, b or c".
std::string spoken_list(const std::vector<std::string>& items) {
  std::string text;
  for (std::size_t i = 0; i < items.size(); ++i)
    text += (i == 0 ? "" : i + 1 == items.size() ? " or " : ", ") + items[i];
  return text;
}
}  // namespace

const Codec& find_codec(const std::string& name) {
  std::vector<std::string> names;
  for (const Codec& c : kCodecs) {
    if (name == c.name) return c;
    names.push_back(c.name);
  }
  throw OutputError("unknown video codec '" + name + "': choose " + spoken_list(names));
}

const Container* container_for(const std::filesystem::path& path) {
  const std::string ext = lower_extension_of(path);
  for (const Container& c : kContainers)
    if (ext == c.extension) return &c;
  return nullptr;
}

const Container& find_container(const std::filesystem::path& path) {
  if (const Container* c = container_for(path)) return *c;
  std::vector<std::string> names;
  for (const Container& c : kContainers) names.push_back(std::string(c.extension) + " (" + find_codec(c.codec).label + ")");
  throw OutputError("cannot tell the video format of '" + path.string() + "': name it " + spoken_list(names));
}

const Container* streaming_container(const std::string& format) {
  for (const Container& c : kContainers)
    if (c.streams && format == c.format) return &c;
  return nullptr;
}

bool carries_alpha(const Codec& codec) { return codec.alpha_pixels != AV_PIX_FMT_NONE; }

std::string codec_labels(bool (*has)(const Codec&)) {
  std::vector<std::string> labels;
  for (const Codec& c : kCodecs)
    if (has(c)) labels.push_back(c.label);
  return spoken_list(labels);
}

std::string preset_names(const Codec& codec) {
  std::vector<std::string> names;
  for (const char* const* p = codec.presets; p && *p; ++p) names.push_back(*p);
  return spoken_list(names);
}

}  // namespace vibra::render
