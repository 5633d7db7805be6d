// The encoder's options that vibra render and vibra lecture share: --codec, --quality, --crf, --preset, --threads.
#pragma once
#include <CLI/CLI.hpp>
#include <string>

#include "render/encode/frame_sink.hpp"

namespace vibra::cli {

/// Declares --codec, --quality, --crf, --preset and --threads into `video`,
/// each checked against the table of ranges. The helps that differ between
/// commands (which codecs its outputs take, what its threads do) are given.
void add_encoder_options(CLI::App& cmd, render::VideoSettings& video, const std::string& codec_help,
                         const std::string& quality_help, const std::string& threads_help);

}  // namespace vibra::cli
