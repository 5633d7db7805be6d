// Registers vibra concat: joins segment videos into one without re-encoding.
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "cli/wrote_message.hpp"
#include "core/error.hpp"
#include "render/encode/join/video_concat.hpp"
#include "render/output/output_path.hpp"

namespace vibra::cli {

namespace {
struct ConcatOptions {
  std::vector<std::string> parts;
  std::string output;
  bool quiet = false;
};

void run(const ConcatOptions& o) {
  if (o.parts.empty()) throw UsageError("vibra concat needs the segment videos: vibra concat PART... -o OUT");
  if (o.output.empty()) throw UsageError("vibra concat needs an output: add -o OUT.mp4 (or .mkv, .webm)");
  const std::vector<std::filesystem::path> parts(o.parts.begin(), o.parts.end());
  const render::ConcatSummary joined = render::concat_segments(parts, o.output);
  say_wrote(o.quiet, render::resolve_output(o.output).shown() + " (" + std::to_string(joined.frames) + " frames from " +
                         std::to_string(joined.parts) + " segments, no re-encoding)");
}
}  // namespace

void add_concat_command(CLI::App& app) {
  auto o = std::make_shared<ConcatOptions>();
  CLI::App* cmd = app.add_subcommand(
      "concat", "Join the segment videos of one render (vibra render --segment) by copying, without re-encoding");
  cmd->add_option("PART", o->parts, "Segment videos, in any order: every segment of the render, once")->required();
  add_output_option(*cmd, o->output, "The joined video (.mp4, .mkv or .webm, as the parts)")->required();
  cmd->add_flag("-q,--quiet", o->quiet, "No message");
  cmd->footer(
      "\nEach part must be a segment of the same render (same scene, parameters and video options). The parts'\n"
      "codec parameters, frame ranges and timestamps are checked, and a wrong or missing part is named; OUT is\n"
      "written only when every check passes. Example:\n"
      "  vibra render --segment 0/2 -o lecture.mp4 && vibra render --segment 1/2 -o lecture.mp4\n"
      "  vibra concat lecture.seg-*-of-2.mp4 -o lecture.mp4\n");
  cmd->callback([o] { run(*o); });
}

}  // namespace vibra::cli
