// Registers vibra lecture: a storyboard's shots played into one video.
#include <cstdlib>
#include <memory>
#include <optional>
#include <string>

#include "cli/command_line.hpp"
#include "cli/commands.hpp"
#include "cli/encoder_options.hpp"
#include "cli/option_checks.hpp"
#include "cli/segment_option.hpp"
#include "core/error.hpp"
#include "core/stop_flag.hpp"
#include "jobs/lecture_job.hpp"

namespace vibra::cli {

namespace {
struct LectureOptions {
  std::string storyboard;
  std::string output;
  std::optional<int> shot;
  std::string segment, size;
  bool present = false;
  std::string shots_dir;
  bool force = false;
  bool quiet = false;
  bool mute = false, script = false;
  render::VideoSettings video;
};

void run(const LectureOptions& o) {
  scenes::LectureRequest request;
  request.storyboard = o.storyboard;
  request.output = o.output.empty() ? std::filesystem::path(o.storyboard).stem().string() + ".mp4" : o.output;
  request.shot = o.shot;
  request.size = o.size;
  if (!o.segment.empty()) request.segment = parse_segment_option(o.segment, [](const char* name) { return std::getenv(name); });
  request.video = o.video;
  request.present = o.present;
  request.shots_dir = o.shots_dir;
  request.force = o.force;
  request.quiet = o.quiet;
  request.mute = o.mute;
  request.script = o.script;
  request.command_line = command_line();
  quiet_long_work(o.quiet);
  scenes::run_lecture(request);
}
}  // namespace

void add_lecture_command(CLI::App& app) {
  auto o = std::make_shared<LectureOptions>();
  CLI::App* cmd = app.add_subcommand(
      "lecture", "Play a storyboard's shots (title cards and scenes) in order into one video with chapters and subtitles");
  cmd->add_option("STORYBOARD", o->storyboard, "A TOML file: title, size, fps, then [[shot]] tables")->required();
  add_output_option(*cmd, o->output,
                    "OUT.mp4 or OUT.webm (with OUT.vtt beside it), or PAGE.html (a page with a chapter list, its MP4, "
                    "WebM and subtitles in PAGE_files/); default: STORYBOARD.mp4");
  cmd->add_option("--size", o->size, "Frame size WxH instead of the storyboard's, e.g. 640x360 for a draft");
  cmd->add_option("--shot", o->shot, "Render shot N (1, 2, ...) alone, with its chapter and subtitles");
  cmd->add_option("--segment", o->segment,
                  "K/N: render only the shots S with (S-1) mod N = K into OUT.shot-S.EXT beside the output, for a "
                  "cluster; a run without --segment then joins them (auto, auto/N: as vibra render --segment)");
  cmd->add_flag("--present", o->present,
                "With -o TALK.html: a presentation, a slide a shot, each shot waiting for the presenter's keys "
                "(then = hold, loop or next; intro = seconds played once before a loop), a speaker view (S), "
                "each shot's video and first frame in TALK_files/");
  cmd->add_option("--shots-dir", o->shots_dir,
                  "DIR: every shot as its own video and first-frame PNG (NN-title.mp4, NN-title.png), with "
                  "index.md and beamer.tex, for slide programs; rendered once with the other outputs");
  add_encoder_options(*cmd, o->video, "Video codec: h264 (.mp4) or vp9, vp8 (.webm); default from the extension",
                      "draft, medium or high", "Encoder threads (default: one per core)");
  cmd->add_flag("--force", o->force,
                "Replace OUT.vtt, PAGE_files/ or a shot file that vibra did not write for this lecture");
  cmd->add_flag("--mute", o->mute, "No sound track: the shots keep the lengths their speech (say, audio) gives them");
  cmd->add_flag("--script", o->script,
                "Write the narration script (each shot's number, start, length, title and words) to standard output "
                "and render nothing: to record takes from");
  add_allow_unstable_flag(*cmd);
  cmd->add_flag("-q,--quiet", o->quiet, "No progress or messages");
  cmd->footer(
      "\nA shot is a title card (card = \"text\", equation = \"LaTeX\", seconds = 3) or a scene (scene = NAME or a\n"
      "scene file, set = { KEY = VALUE }, any key vibra render takes: compare, panels, layout, slow, pause, ...;\n"
      "seconds = the shot's length, or speed; notes = [\"T0-T1: text\"] become subtitles). Each shot is a chapter.\n"
      "say = \"words\" on a shot speaks them (flite, offline; voice = \"slt\"), audio = \"take.wav\" plays a recording;\n"
      "a shot without seconds lasts as long as its speech.\n"
      "The whole storyboard is checked before anything is rendered. docs/lecture.md has a complete example.\n"
      "Examples:\n"
      "  vibra lecture examples/damped_pendulum_lecture.toml -o lecture.mp4\n"
      "  vibra lecture examples/damped_pendulum_lecture.toml -o lecture.html\n"
      "  vibra lecture examples/damped_pendulum_lecture.toml -o talk.html --present\n"
      "  vibra lecture examples/damped_pendulum_lecture.toml --shot 2 -o shot2.webm\n");
  cmd->callback([o] { run(*o); });
}

}  // namespace vibra::cli
