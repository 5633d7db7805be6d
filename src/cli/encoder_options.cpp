// The encoder's options that vibra render and vibra lecture share: --codec, --quality, --crf, --preset, --threads.
#include "cli/encoder_options.hpp"

#include "cli/option_checks.hpp"

namespace vibra::cli {

void add_encoder_options(CLI::App& cmd, render::VideoSettings& video, const std::string& codec_help,
                         const std::string& quality_help, const std::string& threads_help) {
  cmd.add_option("--codec", video.codec, codec_help);
  cmd.add_option("--quality", video.quality, quality_help)->capture_default_str();
  cmd.add_option("--crf", video.crf, "Constant rate factor (overrides --quality)")->check(ranged("--crf"));
  cmd.add_option("--preset", video.preset, "x264 preset, e.g. veryfast, medium");
  cmd.add_option("--threads", video.threads, threads_help)->check(ranged("--threads"));
}

}  // namespace vibra::cli
