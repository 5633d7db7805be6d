// Registers vibra render: its flags turned into scene settings and handed to the render job.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cli/command_line.hpp"
#include "cli/commands.hpp"
#include "cli/encoder_options.hpp"
#include "cli/option_checks.hpp"
#include "cli/segment_option.hpp"
#include "core/error.hpp"
#include "core/input/expression.hpp"
#include "core/input/quoted_value.hpp"
#include "core/stop_flag.hpp"
#include "core/input/value_ranges.hpp"
#include "scenes/diagrams/diagram_registry.hpp"
#include "jobs/live_page_job.hpp"
#include "jobs/render_job.hpp"
#include "scenes/config/scene_config.hpp"

namespace vibra::cli {

namespace {
struct RenderOptions {
  std::string scene = "pendulum";
  std::vector<std::string> settings;
  std::string output;
  std::string size, layout, fps, speed;
  bool frame_per_step = false;
  bool frames_player = false;
  long long every = 1;
  std::string window, window_mode;
  std::string compare;
  std::string panels;
  bool energy_bars = false;
  std::string annotate;
  std::string exaggerate;
  std::optional<std::string> title;
  bool equation = false;
  std::vector<std::string> notes;
  std::optional<std::string> at;  ///< a time: a number or an expression, as --set values take
  std::string segment;
  std::vector<std::string> slow, pauses;
  bool skip_existing = false;
  bool force = false;
  bool quiet = false;
  bool live = false;
  render::VideoSettings video;
};

std::string scene_keys_help() {
  std::string out = "\nScene keys (in a scene file, or --set KEY=VALUE; any other key goes to the model):\n";
  char line[512];
  for (const auto& key : scenes::scene_keys()) {
    std::snprintf(line, sizeof line, "  %-20s %-58s default: %s\n", key.name.c_str(), key.meaning.c_str(),
                  key.default_value.c_str());
    out += line;
  }
  out += "\nBuilt-in scenes (vibra render NAME):\n";
  for (const auto& name : scenes::builtin_scene_names()) {
    std::snprintf(line, sizeof line, "  %-20s %s\n", name.c_str(), scenes::builtin_scene_summary(name).c_str());
    out += line;
  }
  out += "\nDiagrams (scene key diagram; a model name as SCENE draws its default one):\n";
  for (const auto& kind : scenes::all_diagrams()) {
    std::string models;
    for (const auto& m : kind.models) models += (models.empty() ? "" : ", ") + m;
    std::snprintf(line, sizeof line, "  %-20s [%s] %s\n", kind.name.c_str(), models.c_str(), kind.summary.c_str());
    out += line;
  }
  out += "\nExamples:\n  vibra render                                   # pendulum.mp4\n"
         "  vibra render pendulum_book -o frames/tmp_%04d.png\n"
         "  vibra render --set Theta=40 --set alpha=0.8 -o lecture.webm\n"
         "  vibra render --at 3.2 -o still.svg\n"
         "  vibra render --slow 2-4:4 --pause 3:1 -o lecture.mp4  # t = 2..4 four times slower, t = 3 held 1 s\n"
         "  vibra render spring_dashpot --panels u,phase,energy --energy-bars --at 5 -o still.png\n"
         "  vibra render --title \"The damped pendulum\" --equation --note \"2-4: drag takes energy out @theta\"\n"
         "  vibra render --segment 1/3 -o lecture.mp4             # lecture.seg-1-of-3.mp4; then vibra concat\n"
         "  vibra render --set periods=40 -o lecture.html        # video, zoomable plots, CSV\n"
         "  vibra render spring --compare scheme=forward-euler,backward-euler,crank-nicolson,rk4 -o schemes.mp4\n"
         "  vibra render undamped --compare dt=0.2,0.1,0.05 --layout grid --set periods=40 --window 4periods -o dt.mp4\n"
         "  vibra render --transparent -o overlay.webm          # or .mov, or frames/tmp_%04d.png\n"
         "  vibra render -o - --format y4m | ffplay -            # watch while it renders\n";
  return out;
}

/// --at's time, read as --set values are: 3.2, pi/2, 2*pi.
double still_time(const std::string& text) {
  const auto not_a_time = [&] {
    return UsageError("--at " + quoted_value(text) + " is not a time: give a number or an expression, e.g. --at 3.2 or --at pi/2");
  };
  double time = 0;
  try {
    time = evaluate_constant("--at", text);
  } catch (const UsageError&) {
    throw not_a_time();
  }
  if (!std::isfinite(time)) throw not_a_time();  // inf, 1/0
  return in_range("--at", time, text);  // a number, but too large: the range says so
}

/// The settings of the command line, as KEY=VALUE: where a live page starts from.
std::vector<std::string> setting_lines(const std::vector<scenes::Setting>& given) {
  std::vector<std::string> lines;
  for (const scenes::Setting& s : given) lines.push_back(s.key + "=" + s.value);
  return lines;
}

/// --live's page: the options a page of controls cannot take are refused.
void run_live(const RenderOptions& o, const scenes::RenderRequest& request, const std::vector<scenes::Setting>& given) {
  if (o.at || !o.segment.empty() || o.frames_player || o.skip_existing)
    throw UsageError("--live writes a page that draws any time itself: drop --at, --segment, --frames-player and "
                     "--skip-existing");
  scenes::LivePageRequest live{o.scene, request.scene, setting_lines(given),
                               o.output.empty() ? o.scene + ".html" : o.output, o.force, o.quiet};
  scenes::run_live_page(live);
}

void run(const RenderOptions& o) {
  scenes::RenderRequest request;
  request.scene = scenes::load_scene(o.scene);
  std::vector<scenes::Setting> given;  // every setting of the command line, in order
  auto apply = [&](const scenes::Setting& setting) {
    scenes::apply_setting(request.scene, setting);
    given.push_back(setting);
  };
  for (const auto& assignment : o.settings) {
    const auto eq = assignment.find('=');
    if (eq == std::string::npos || eq == 0)
      throw UsageError("'--set " + assignment + "' is not KEY=VALUE: write e.g. --set Theta=40");
    apply({assignment.substr(0, eq), assignment.substr(eq + 1), "--set"});
  }
  auto flag = [&](const std::string& key, const std::string& value, const char* name) {
    if (!value.empty()) apply({key, value, name});
  };
  flag("size", o.size, "--size");
  flag("layout", o.layout, "--layout");
  flag("fps", o.fps, "--fps");
  flag("video_speed", o.speed, "--speed");
  flag("window", o.window, "--window");
  flag("window_mode", o.window_mode, "--window-mode");
  flag("compare", o.compare, "--compare");
  flag("panels", o.panels, "--panels");
  flag("annotate", o.annotate, "--annotate");
  flag("exaggerate", o.exaggerate, "--exaggerate");
  for (const auto& range : o.slow) apply({"slow", range, "--slow"});
  for (const auto& pause : o.pauses) apply({"pause", pause, "--pause"});
  if (o.energy_bars) apply({"energy_bars", "true", "--energy-bars"});
  if (o.title) apply({"title", *o.title, "--title"});
  if (o.equation) apply({"equation", "true", "--equation"});
  for (const auto& note : o.notes) apply({"notes", note, "--note"});
  if (o.frame_per_step) apply({"frame_per_step", "true", "--frame-per-step"});
  if (o.live) return run_live(o, request, given);
  request.output = o.output.empty() ? request.scene.name + ".mp4" : o.output;
  if (o.at) request.at = still_time(*o.at);
  request.frames_player = o.frames_player;
  request.csv_every = o.every;
  request.command_line = command_line();
  request.quiet = o.quiet;
  quiet_long_work(o.quiet);
  request.video = o.video;
  if (!o.segment.empty()) request.segment = parse_segment_option(o.segment, [](const char* name) { return std::getenv(name); });
  request.skip_existing = o.skip_existing;
  request.force = o.force;
  scenes::run_render(request);  // -o -: a failed write ends it with StandardOutputFailed, for main to handle
}
/// The flags that set scene keys (each handed to apply_setting as text, by run()).
void add_scene_flags(CLI::App& cmd, RenderOptions& o) {
  cmd.add_option("--size", o.size, "Frame size WxH, e.g. 1920x1080");
  cmd.add_option("--fps", o.fps, "Frames per second");
  cmd.add_option("--speed", o.speed, "Simulated time units per second of video");
  cmd.add_flag("--frame-per-step", o.frame_per_step, "One frame per solver step (the book's animation)");
  cmd.add_option("--slow", o.slow,
                 "T0-T1:FACTOR: simulated times T0 to T1 play FACTOR times slower (2-4:4 is a quarter speed; 0.5 "
                 "twice as fast); repeatable, ranges may not overlap");
  cmd.add_option("--pause", o.pauses, "T:SECONDS: hold simulated time T for SECONDS of video (3:1); repeatable");
  cmd.add_option(
      "--layout", o.layout,
      "fbd (the diagram alone), fbd+plot, plot (any model's moving plot), or grid (a panel per compared run)");
  cmd.add_option("--compare", o.compare,
                 "KEY=V1,V2,...: one run per value (up to 8) of scheme, dt, steps_per_period or a model key, drawn "
                 "together: the first solid, the others as ghosts in their own colours, a curve each in every panel");
  cmd.add_option("--window", o.window, "Plot window: a time or N periods (8periods); default the whole run");
  cmd.add_option("--window-mode", o.window_mode, "drawing, movement (default) or jumps");
  cmd.add_option("--panels", o.panels,
                 "Panels beside the diagram, top to bottom (layout fbd+plot): the model's columns, phase (the main "
                 "quantity against its velocity), energy ((E - E0)/|E0|), error (against the exact solution), period "
                 "(each measured period against the exact one); default: the system's own");
  cmd.add_flag("--energy-bars", o.energy_bars,
               "Kinetic, potential and dissipated energy as bars beside the diagram, on one scale over the run");
  cmd.add_option("--annotate", o.annotate,
                 "Marks of the book's figures on the diagram: geometry (the pendulum's unit vectors i_r and i_theta, "
                 "its pivot (x0, y0) and length L, Fig 1.21)");
  cmd.add_option("--exaggerate", o.exaggerate,
                 "F: the bumpy road's heights (road and body) drawn F times larger, said under the diagram; default: "
                 "chosen from the run when its motion is too small to see, 1 for true scale");
  cmd.add_option("--title", o.title, "A title across the top of the frame (text; $math$ in the LaTeX subset)");
  cmd.add_flag("--equation", o.equation,
               "The model's equation of motion typeset under the title; with --compare scheme=..., each scheme's "
               "update formula under its legend entry");
  cmd.add_option("--note", o.notes,
                 "\"T0-T1: TEXT\": a callout shown for T0 <= t <= T1 (TEXT may hold $math$; \"... @PANEL\" points at "
                 "that panel's curve at T0, e.g. @theta or @2); repeatable");
}

/// The flags of the video encoder.
void add_video_flags(CLI::App& cmd, render::VideoSettings& video) {
  add_encoder_options(cmd, video, "Video codec: h264, vp9, vp8, theora, gif (default from the extension)",
                      "draft, medium, high, or lossless (H.264 or VP9: decodes to exactly the frames drawn)",
                      "Threads for PNG compression and the encoder (default: one per core)");
  cmd.add_option("--format", video.format,
                 "With -o - (standard output), a pipe or a device: y4m (raw frames, for ffplay -), nut or matroska "
                 "(H.264)");
  cmd.add_flag("--transparent", video.transparent,
               "No background: PNG with alpha, .webm (VP9 with alpha), .mov (ProRes 4444), SVG/PDF without the "
               "background rectangle");
}
}  // namespace

void add_render_command(CLI::App& app) {
  auto o = std::make_shared<RenderOptions>();
  CLI::App* cmd = app.add_subcommand("render", "Draw a scene's frames: video, PNG frames, or one still");
  cmd->add_option("SCENE", o->scene, "Built-in scene name or a TOML scene file")->capture_default_str();
  cmd->add_option("--set", o->settings, "KEY=VALUE: a scene key or a model key, repeatable");
  add_output_option(
      *cmd, o->output,
      "OUT.mp4|.webm|.mkv|.mov|.ogv|.gif|.yuv|.nut, PAGE.html (an interactive page, its MP4, WebM and CSV "
      "in PAGE_files/), frames/tmp_%04d.png or a directory, - for standard output or a pipe or device "
      "(with --format), or a still .png/.svg/.pdf with --at (default: SCENE.mp4); missing folders are "
      "made");
  add_scene_flags(*cmd, *o);
  cmd->add_flag("--live", o->live,
                "With -o PAGE.html: a page that re-solves and draws the scene in the browser as its keys' controls move "
                "(PAGE_files/ holds the WebAssembly and fonts)");
  cmd->add_flag("--frames-player", o->frames_player, "With -o PAGE.html: PNG frames and a page that steps through them");
  cmd->add_option("--every", o->every, "With -o PAGE.html: the CSV beside the page keeps every K-th step (and the last)")
      ->check(ranged("--every"));
  cmd->add_option("--at", o->at,
                  "Render one still at this time (a number or an expression, e.g. 3.2 or pi/2): the frame the same "
                  "render shows then, with the same --fps and --speed (labels keep spots over frames)");
  add_video_flags(*cmd, o->video);
  cmd->add_option("--segment", o->segment,
                  "K/N: only frames [K F/N, (K+1) F/N) of the F frames, to OUT.seg-K-of-N.EXT (video) or the frames' own "
                  "numbers (PNG); auto: K and N of a Slurm job array; auto/N: K from JOB_COMPLETION_INDEX");
  cmd->add_flag("--skip-existing", o->skip_existing,
                "Do nothing when the output (or this segment) is already complete at its final path");
  cmd->add_flag("--force", o->force,
                "Replace a page's PAGE_files/ folder, or a segment's file, that vibra did not write for this output");
  add_allow_unstable_flag(*cmd);
  cmd->add_flag("-q,--quiet", o->quiet, "No progress or messages");
  cmd->footer(scene_keys_help());
  cmd->callback([o] { run(*o); });
}

}  // namespace vibra::cli
