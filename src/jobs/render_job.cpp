// The render job: a scene config and model solved and drawn into frames, a video, a still or a page.
#include "jobs/render_job.hpp"

#include <cairo.h>

#include <algorithm>
#include <functional>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <span>

#include "core/comparison_trajectory.hpp"
#include "core/error.hpp"
#include "core/models/model.hpp"
#include "core/input/quoted_value.hpp"
#include "render/draw/canvas.hpp"
#include "render/draw/text.hpp"
#include "render/encode/output_kind.hpp"
#include "render/encode/png/png_sequence.hpp"
#include "render/encode/join/video_concat.hpp"
#include "render/output/output_error.hpp"
#include "render/output/output_path.hpp"
#include "render/output/ownership_manifest.hpp"
#include "render/output/place_together.hpp"
#include "render/output/progress.hpp"
#include "render/output/standard_output.hpp"
#include "render/output/stop_signal.hpp"
#include "render/output/temporary_file.hpp"
#include "render/page/html_page.hpp"
#include "scenes/diagrams/comparison_labels.hpp"
#include "scenes/timing/frame_clock.hpp"
#include "scenes/overlays/note_room.hpp"
#include "scenes/panels/comparison_page_plots.hpp"
#include "scenes/panels/history_feed.hpp"
#include "scenes/panels/page_plot_collector.hpp"
#include "scenes/overlays/run_caption.hpp"
#include "jobs/run_csv_file.hpp"
#include "scenes/scene_factory.hpp"

namespace vibra::scenes {

namespace {

/// A hash (FNV-1a) of everything that shapes a render's frames and their
/// coding, so that segments of different renders are told apart. Threads are
/// left out: they change how fast, not what.
std::uint64_t render_fingerprint(const RenderRequest& r, const std::string& caption, long long frames) {
  const SceneConfig& c = r.scene;
  std::string text = c.name + '\n' + c.model + '\n' + caption + '\n';
  for (const auto& s : c.model_settings) text += s.key + '=' + s.value + '\n';
  if (!c.compare.empty()) text += "compare " + c.compare + '\n';
  if (!c.title.empty()) text += "title " + c.title + '\n';
  if (c.equation) text += "equation\n";
  for (const auto& note : c.notes) text += "note " + note + '\n';
  char numbers[512];
  const auto& k = c.colors;
  std::snprintf(numbers, sizeof numbers, "%d %d %.17g %.17g %d %d %d %.17g %lld", c.width, c.height, c.fps, c.speed,
                int(c.frame_per_step), int(c.layout), int(c.window_mode), c.drag_magnification, frames);
  text += numbers;
  for (const render::Color& color : {k.background, k.bob, k.wire, k.gravity, k.wire_force, k.drag}) {
    std::snprintf(numbers, sizeof numbers, " %.17g %.17g %.17g %.17g", color.r, color.g, color.b, color.a);
    text += numbers;
  }
  text += '\n' + c.window + '\n' + r.video.codec + '\n' + r.video.quality + '\n' + std::to_string(r.video.crf) + '\n' +
          r.video.preset + (r.video.transparent ? "\ntransparent" : "") + '\n' + c.pacing.describe();
  std::uint64_t hash = 14695981039346656037ull;
  for (unsigned char byte : text) hash = (hash ^ byte) * 1099511628211ull;
  return hash;
}

namespace fs = std::filesystem;

/// Where the frames go: one target, or for a page its videos or frames.
struct Outputs {
  std::vector<std::string> targets;  ///< what the sinks write: video files, a frame pattern, or "-" (a stream)
  std::vector<std::string> links;    ///< a page's videos, relative to the page
  std::string frames_prefix;         ///< player pages: frame name prefix relative to the page
  int digits = 4;
};

/// A segment's file may be overwritten when vibra wrote it (it carries a
/// segment tag: a restart, or another split of the same output), or with --force.
void check_segment_file(const RenderRequest& r, const fs::path& file, const render::FrameSegment& segment) {
  render::resolve_output_file(file);
  std::error_code ec;
  if (r.force || !fs::exists(file, ec)) return;
  if (!render::read_segment_tag(file))
    throw render::OutputError("'" + file.string() + "' exists and was not written by vibra for segment " +
                              std::to_string(segment.index) + "/" + std::to_string(segment.count) + " of " + r.output +
                              ": move it away, or add --force to overwrite it");
}

/// Each frame's name is a file that may be written (not a folder, not an
/// input). Only a name that exists can be either, so the folder's entries
/// are checked, not every name: a render of 1e9 frames (a tiny --speed)
/// checks as fast as one of ten, and stops at Ctrl-C.
void check_frame_names(const std::string& target, const render::FrameSegment& segment) {
  const render::FramePattern pattern = render::parse_frame_pattern(target, segment.total);
  std::error_code ec;
  long long seen = 0;
  for (const auto& entry : fs::directory_iterator(pattern.directory, ec)) {
    if ((++seen & 0xff) == 0) render::throw_if_stop_requested();
    const std::optional<long long> k = pattern.index_of(entry.path().filename().string());
    if (k && *k >= segment.first() && *k < segment.end()) render::resolve_output_file(entry.path());
  }
}

Outputs plan_outputs(const RenderRequest& r, const render::FrameSegment& segment, bool stream, const fs::path& staged) {
  if (stream) return {{"-"}, {}, "", 4};
  if (r.segment && render::is_video_path(r.output)) return {{segment.file_name(r.output)}, {}, "", 4};
  if (staged.empty()) return {{r.output}, {}, "", 4};
  const std::string stem = fs::path(r.output).stem().string();
  const std::string folder = companion_folder(r.output).filename().string() + "/";
  if (!r.frames_player)
    return {{(staged / (stem + ".mp4")).string(), (staged / (stem + ".webm")).string()},
            {folder + stem + ".mp4", folder + stem + ".webm"}, "", 4};
  const std::string pattern = (staged / "frame_%04d.png").string();
  return {{pattern}, {}, folder + "frame_", render::parse_frame_pattern(pattern, segment.total).digits};
}

/// Whether every frame name of `pattern` in the segment holds a file.
bool frames_complete(const std::string& pattern, const render::FrameSegment& segment) {
  const render::FramePattern names = render::parse_frame_pattern(pattern, segment.total);
  std::error_code ec;
  for (long long k = segment.first(); k < segment.end(); ++k) {
    if ((k & 0xff) == 0) render::throw_if_stop_requested();
    if (!fs::is_regular_file(names.name(k), ec)) return false;
  }
  return true;
}

/// --skip-existing: whether the outputs are complete at their final paths.
/// Outputs are put in place only when complete, so a file there is proof (a
/// folder is not); a segment video must also hold this segment (not one of
/// another split), a page its companions.
bool already_complete(const RenderRequest& r, const Outputs& outputs, const render::FrameSegment& segment) {
  std::error_code ec;
  if (r.at) return fs::is_regular_file(r.output, ec);
  if (render::lower_extension_of(r.output) == ".html") {
    const fs::path folder = companion_folder(r.output);
    const std::string stem = fs::path(r.output).stem().string();
    if (!fs::is_regular_file(r.output, ec) || !fs::is_regular_file(folder / (stem + ".csv"), ec)) return false;
    if (r.frames_player) return frames_complete((folder / "frame_%04d.png").string(), segment);
    return fs::is_regular_file(folder / (stem + ".mp4"), ec) && fs::is_regular_file(folder / (stem + ".webm"), ec);
  }
  const std::string& target = outputs.targets.front();
  if (target == "-") return false;
  if (render::is_video_path(target))
    return fs::is_regular_file(target, ec) && (!r.segment || render::read_segment_tag(target) == segment);
  return frames_complete(target, segment);
}

render::PageFacts page_facts(const RenderRequest& r, long long frames, const Parameters& p, const TimeMesh& mesh,
                             double speed) {
  auto format = [](const char* pattern, double x) {
    char text[64];
    std::snprintf(text, sizeof text, pattern, x);
    return std::string(text);
  };
  render::PageFacts facts = {{"scene", r.scene.name}};
  for (auto& fact : run_facts(r.scene.model, p, mesh)) facts.push_back(std::move(fact));
  if (!r.scene.compare.empty()) {  // the compared key's values instead of the first member's
    const ComparisonRequest c = parse_comparison(r.scene.compare);
    const std::string shown = c.key == "steps_per_period" ? "dt" : c.key == "periods" ? "T" : c.key;
    std::erase_if(facts, [&](const auto& f) { return f.first == shown; });
    std::string values;
    for (const auto& v : c.values) values += (values.empty() ? "" : ", ") + v;
    facts.emplace_back("compared", c.key + " = " + values);
  }
  facts.emplace_back("frames", std::to_string(frames) + " at " + format("%g", r.scene.fps) + " fps (" +
                                   format("%.3g", frames / r.scene.fps) + " s of video)");
  facts.emplace_back("speed", r.scene.frame_per_step ? "one frame per step"
                                                     : format("%.4g", speed) + " time units per second of video");
  if (!r.scene.pacing.empty()) facts.emplace_back("pacing", r.scene.pacing.describe());
  facts.emplace_back("size", std::to_string(r.scene.width) + "x" + std::to_string(r.scene.height));
  if (r.scene.equation) facts.emplace_back("equation", model_equation(find_model(r.scene.model), p));
  for (const std::string& note : r.scene.notes) facts.emplace_back("note", note);
  return facts;
}

/// A page that links its videos (or frames) and CSV, with the run's time series.
std::string page_html(const RenderRequest& r, const Outputs& outputs, const FrameClock& clock, render::PageFacts facts,
                      std::vector<render::PagePanel> panels, const std::string& csv_link) {
  render::LecturePage page;
  page.title = r.scene.title.empty() ? "vibra: " + r.scene.name : r.scene.title;
  render::PageMedia& media = page.media;
  media.width = r.scene.width + (r.scene.width & 1);  // videos are even-sized
  media.height = r.scene.height + (r.scene.height & 1);
  media.frames = clock.frames();
  media.fps = r.scene.fps;
  media.frame_interval = clock.interval();
  if (clock.time_map())
    for (const TimePiece& piece : clock.time_map()->pieces())
      media.time_map.push_back({piece.video, piece.simulated, piece.rate});
  if (clock.time_map())  // the end: the run's last time, held
    media.time_map.push_back({clock.time_map()->duration(), clock.time_map()->end(), 0});
  if (r.frames_player) {
    media.kind = render::PageMedia::Kind::frames;
    media.frames_prefix = outputs.frames_prefix;
    media.digits = outputs.digits;
    media.width = r.scene.width, media.height = r.scene.height;
  } else {
    media.kind = render::PageMedia::Kind::video;
    for (const auto& link : outputs.links) {
      media.videos.push_back(link);
      page.downloads.push_back({render::lower_extension_of(link) == ".mp4" ? "MP4 video" : "WebM video", link});
    }
  }
  page.downloads.push_back({"CSV of the run", csv_link});
  page.panels = std::move(panels);
  page.facts = std::move(facts);
  page.command_line = r.command_line;
  return render::lecture_page_html(page);
}

/// The closing line's list for a page: the page, then every companion.
std::string page_written(const RenderRequest& r, const render::OutputTarget& target, long long frames) {
  const fs::path folder = companion_folder(r.output);
  const std::string stem = fs::path(r.output).stem().string();
  std::string written = target.shown();
  const std::string count = " (" + std::to_string(frames) + " frames)";
  if (!r.frames_player) {
    for (const char* ext : {".mp4", ".webm"}) written += ", " + (folder / (stem + ext)).string() + count;
  } else {
    const render::FramePattern names = render::parse_frame_pattern((folder / "frame_%04d.png").string(), frames);
    written += ", " + std::to_string(frames) + " frames " + names.name(0).string() + " ... " +
               names.name(std::max(0LL, frames - 1)).string();
  }
  return written + " and " + (folder / (stem + ".csv")).string();
}

/// Writes one picture at the request's time: PNG, SVG or PDF.
void write_still(const RenderRequest& r, const render::OutputTarget& target, Scene& scene, std::span<const double> row) {
  const std::string ext = render::lower_extension_of(r.output);
  render::TemporaryFile file(target.file);
  const int w = r.scene.width, h = r.scene.height;
  if (ext == ".png") {
    render::Canvas canvas = render::Canvas::image(w, h);
    scene.draw(canvas, row);
    canvas.flush();
    if (cairo_surface_write_to_png(canvas.surface(), file.path().c_str()) != CAIRO_STATUS_SUCCESS)
      throw render::OutputError("writing '" + r.output + "' failed (disk full? unwritable?)");
  } else {
    render::Canvas canvas = ext == ".svg" ? render::Canvas::svg(file.path(), w, h) : render::Canvas::pdf(file.path(), w, h);
    scene.draw(canvas, row);
    canvas.finish();
  }
  file.commit();
  if (!r.quiet) std::fprintf(stderr, "vibra: wrote %s (t = %g)\n", one_line_message(target.shown(), 4096).c_str(), row[0]);
}

/// Draws, on a canvas thrown away, the frames of drawn frame `d`'s label chain
/// before it, so that its labels keep the spots a whole render gives them.
/// The scratch canvas tracks damage when the frames after it go to one that
/// does, so that the layers made on it are made alike.
void replay_label_chain(Scene& scene, const FrameClock& clock, long long d, int width, int height, bool track_damage,
                        const std::function<std::span<const double>(double)>& row_at) {
  scene.set_label_chain(d / kLabelChainFrames);
  const long long start = d - d % kLabelChainFrames;
  if (start == d) return;
  render::Canvas scratch = render::Canvas::image(width, height);
  if (track_damage) scratch.track_damage();
  // Nothing of these frames is seen: with everything clipped away Cairo
  // skips the rasterizing, the costly part, while the outlines the labels
  // are placed from are recorded from the paths as ever, and the layers the
  // frames grow (their own canvases) grow alike.
  cairo_rectangle(scratch.cr(), 0, 0, 0, 0);
  cairo_clip(scratch.cr());
  for (long long j = start; j < d; ++j)
    if (!clock.repeats(j)) scene.draw(scratch, row_at(clock.time(j)));
}

}  // namespace

/// A page's companions (videos or frames, and the CSV) go in a folder of
/// their own beside it, PAGE_files/ (as browsers save a page), so the page
/// never writes over a file the user did not name.
fs::path companion_folder(const std::string& page) {
  const fs::path p(page);
  return p.parent_path() / (p.stem().string() + "_files");
}

/// A page's companion folder may be replaced when vibra can prove it wrote
/// it (its manifest lists every file in it, each of the size and hash
/// listed: render/output/ownership_manifest.hpp), or with --force; never
/// when it holds a file the run reads, nor when vibra may not read it (another
/// user's, or mode 000): such a folder is never moved, --force or not.
void check_companion_folder(const fs::path& folder, bool force) {
  std::error_code ec;
  if (!fs::exists(fs::symlink_status(folder, ec))) return;
  render::refuse_input_as_output(folder);
  if (const std::string why = render::why_unreadable(folder); !why.empty())
    throw render::OutputError("'" + folder.string() + "' " + why + ": vibra never moves what it may not read, nor another " +
                              "user's: move it away yourself, or choose another output name");
  long long seen = 0;
  for (const auto& entry : fs::directory_iterator(folder, ec)) {
    if ((++seen & 0xff) == 0) render::throw_if_stop_requested();
    render::refuse_input_as_output(entry.path());
  }
  if (force) return;
  if (const std::string why = render::why_not_vibras(folder); !why.empty())
    throw render::OutputError("'" + folder.string() + "' exists and was not written by vibra for this page: it " + why +
                              ": move it away, or add --force to replace it");
}

namespace {
/// A segment splits a video or frame sequence into files vibra concat joins.
void refuse_unsplittable(const RenderRequest& r, const std::string& ext, bool still, bool stream, bool page) {
  if (still) throw UsageError("--segment splits a video or frame sequence; --at renders one still: drop one of them");
  if (stream)
    throw UsageError("--segment writes files for vibra concat to join: give -o FILE.mp4, .mkv, .webm or PNG frames, "
                     "not a stream (" + r.output + ")");
  if (page)
    throw UsageError("--segment cannot split a page (.html): render segments to .mp4, .mkv, .webm or PNG frames, "
                     "join them with vibra concat");
  if (render::is_video_path(r.output) && ext != ".mp4" && ext != ".mkv" && ext != ".webm")
    throw UsageError("--segment needs a video that keeps timestamps: write .mp4, .mkv or .webm (or PNG frames), "
                     "not " + ext);
}
}  // namespace

/// What a render writes and when, decided by the constructor's stages before
/// any frame and read, never changed, after: the kind of output and where it
/// goes, the run's mesh and frame clock, the frames this run draws, the
/// caption, and a page's companions.
struct RenderPlan {
  /// picture (a still at --at), page, frames, stream (standard output, a
  /// pipe or a device) or video.
  render::OutputKind kind = render::OutputKind::unknown;
  render::OutputTarget target;
  std::optional<Parameters> parameters;
  TimeMesh mesh;
  double speed = 0;
  std::optional<FrameClock> clock;
  render::FrameSegment segment;
  std::string caption;
  fs::path companions;   ///< a page's PAGE_files/
  std::string csv_name;  ///< a page's CSV, in its companions
  Outputs outputs;       ///< what the sinks write (a page's, in its staging folder)
  bool still() const { return kind == render::OutputKind::picture; }
  bool page() const { return kind == render::OutputKind::page; }
  bool stream() const { return kind == render::OutputKind::stream; }
  bool frames() const { return kind == render::OutputKind::frames; }
};

/// Everything run_render works with: its plan, and the run's state.
struct PreparedRender::State {
  RenderRequest r;
  RenderPlan plan;    ///< filled by the constructor's stages, const to play() and after
  bool done = false;  ///< nothing left to play: a still written, or the output already complete
  std::optional<render::TemporaryDirectory> staged;
  std::optional<render::TemporaryFile> page_file;
  std::unique_ptr<Scene> scene;
  std::optional<PagePlotCollector> page_plots;
  std::optional<ComparisonPagePlots> comparison_plots;  ///< a comparison's page: a curve per member
  std::optional<RunCsvFile> csv;
  std::unique_ptr<Trajectory> trajectory;
  std::optional<HistoryFeed> history;
  std::optional<render::Canvas> canvas;
  std::span<const double> row_at(double t) { return history->row_at(t); }
};

PreparedRender::PreparedRender(const RenderRequest& request) : state_(std::make_unique<State>()) {
  state_->r = request;
  plan_output_kind();
  std::unique_ptr<Trajectory> pre_pass = solve_pre_pass();
  if (check_paths_or_skip()) return;
  record_pre_pass(std::move(pre_pass));
  start_render_pass();
}

/// The kind of output (still, page, frames, stream or video file) from -o
/// and the options, refusing combinations that cannot be written.
void PreparedRender::plan_output_kind() {
  State& s = *state_;
  const RenderRequest& r = s.r;
  RenderPlan& plan = s.plan;
  const std::string ext = render::lower_extension_of(r.output);
  const render::OutputKind named = render::classify_output(r.output);
  const bool still = r.at.has_value();
  if (still && !std::isfinite(*r.at))
    throw UsageError("--at " + std::string(std::isnan(*r.at) ? "nan" : "inf") +
                     " is not a time: give a finite time inside the run, e.g. --at 3.2");
  if (still && ext != ".png" && ext != ".svg" && ext != ".pdf")
    throw UsageError("--at renders one still: give -o FILE.png, FILE.svg or FILE.pdf");
  if (!still && (ext == ".svg" || ext == ".pdf"))
    throw UsageError("-o " + r.output + " is one picture: add --at T to choose its time");
  const bool page = named == render::OutputKind::page;
  const bool frames = !still && named == render::OutputKind::frames;  // their names are checked one by one later
  plan.target.named = r.output;
  if (!frames) plan.target = render::resolve_output(r.output, still || page ? render::kNeedsAFile : "");
  const bool stream = plan.target.stream;  // "-", or a pipe or device
  plan.kind = still ? render::OutputKind::picture : stream ? render::OutputKind::stream : named;
  if (r.frames_player && !page) throw UsageError("--frames-player writes a page: give -o PLAYER.html");
  if (r.csv_every < 1) throw UsageError("--every must be at least 1: the page's CSV keeps every K-th step");
  if (r.csv_every != 1 && !page) throw UsageError("--every thins the CSV beside a page: give -o PAGE.html, or drop --every");
  if (r.video.transparent && page && !r.frames_player)
    throw UsageError("a page's MP4 cannot be transparent: add --frames-player (PNG frames), or write .webm or .mov");
  render::check_output_settings(r.output, stream, r.video);
  if (!still && !page && !stream && !frames && named != render::OutputKind::video) {
    if (ext == ".png")
      throw UsageError("-o " + r.output + " is one picture: add --at T, or give a pattern such as frames/tmp_%04d.png");
    throw UsageError("cannot tell what to write from -o " + r.output +
                     ": use .mp4, .webm, .mkv, .mov, .ogv, .gif, .yuv, .html, a frame pattern frames/tmp_%04d.png, a "
                     "directory, - (standard output) with --format, or .png/.svg/.pdf with --at");
  }
  if (r.segment) refuse_unsplittable(r, ext, still, stream, page);
}

/// Solve #1, the pre-pass: the run's mesh, frame clock, caption and
/// segment, checked before any path is touched.
std::unique_ptr<Trajectory> PreparedRender::solve_pre_pass() {
  State& s = *state_;
  const RenderRequest& r = s.r;
  std::vector<Note> notes;  // more at once than a frame shows: refused before any work
  for (const std::string& spec : r.scene.notes) notes.push_back(parse_note(spec));
  refuse_crowded_notes(notes, r.scene.width, r.scene.height);
  render::start_loading_fonts();  // overlaps the solver's pre-pass and the encoder's start
  // A comparison's runs go through the render as one trajectory of wide rows.
  s.plan.parameters.emplace(r.scene.compare.empty() ? model_parameters_of(r.scene)
                                               : comparison_base_of(r.scene, parse_comparison(r.scene.compare).key));
  std::unique_ptr<Trajectory> pre_pass = build_scene_runs(r.scene);  // reads the run's files (a road)
  const TimeMesh mesh = s.plan.mesh = pre_pass->info().mesh;
  if (!std::isfinite(mesh.T)) throw UsageError("a render needs a finite end time: give T or periods");
  const bool still = s.plan.still();
  if (still && (*r.at < 0 || *r.at > mesh.T * (1 + 1e-12)))
    throw UsageError("--at " + short_number(*r.at) + " is outside the run [0, " + short_number(mesh.T) +
                     "]: choose a time inside it, or a longer T");
  if (still) r.scene.pacing.check_inside(mesh.T);  // a still's pacing is checked, though it shows one time
  s.plan.speed = steady_speed(r.scene, mesh);
  const FrameClock& clock = s.plan.clock.emplace(frame_clock_of(r.scene, mesh));
  const auto* runs = dynamic_cast<const ComparisonTrajectory*>(pre_pass.get());
  s.plan.caption = runs ? comparison_caption(r.scene.model, runs->comparison()) : run_caption(r.scene.model, *s.plan.parameters, mesh);
  s.plan.segment = {0, 1, clock.frames()};
  if (r.segment) {
    s.plan.segment = {r.segment->index, r.segment->count, clock.frames(), render_fingerprint(r, s.plan.caption, clock.frames())};
    if (s.plan.segment.frames() == 0)
      throw UsageError("segment " + std::to_string(s.plan.segment.index) + "/" + std::to_string(s.plan.segment.count) +
                       " has no frames: the render has only " + std::to_string(s.plan.segment.total) +
                       ", so use at most that many segments");
  }
  return pre_pass;
}

/// Every path the run will write, checked now that its inputs are known,
/// before any work: the inputs, companions and frame names. True when the
/// output is already complete and --skip-existing skips it.
bool PreparedRender::check_paths_or_skip() {
  State& s = *state_;
  const RenderRequest& r = s.r;
  const bool still = s.plan.still();
  s.plan.companions = s.plan.page() ? companion_folder(r.output) : fs::path();
  if (!s.plan.target.file.empty()) render::refuse_input_as_output(s.plan.target.file);
  if (s.plan.page()) check_companion_folder(s.plan.companions, r.force);
  if (r.segment && render::is_video_path(r.output)) check_segment_file(r, s.plan.segment.file_name(r.output), s.plan.segment);
  if (s.plan.frames()) check_frame_names(r.output, s.plan.segment);
  if (!r.skip_existing || s.plan.stream() ||
      !already_complete(r, still ? Outputs{} : plan_outputs(r, s.plan.segment, false, {}), s.plan.segment))
    return false;
  const std::string done = s.plan.page() || still                                          ? r.output
                           : r.segment && render::is_video_path(r.output) ? s.plan.segment.file_name(r.output)
                                                                            : r.output;
  if (!r.quiet) std::fprintf(stderr, "vibra: %s is already complete: skipped\n", done.c_str());
  s.done = true;
  return true;
}

/// The outputs planned (a page's companions staged), the scene made, and
/// every step of the pre-pass recorded: the scene's fixed view and plot
/// ranges in constant memory, and for a page its time series and CSV.
void PreparedRender::record_pre_pass(std::unique_ptr<Trajectory> pre_pass) {
  State& s = *state_;
  const RenderRequest& r = s.r;
  // A page's companions are made in a temporary folder, and take the place
  // of earlier ones only with the page, when the run is complete.
  if (s.plan.page()) {
    s.staged.emplace(s.plan.companions.parent_path(), s.plan.companions.filename().string());
    s.page_file.emplace(s.plan.target.file);
  }
  s.plan.outputs = r.at ? Outputs{} : plan_outputs(r, s.plan.segment, s.plan.stream(), s.staged ? s.staged->path() : fs::path());
  SceneConfig drawn = r.scene;
  if (r.video.transparent) drawn.colors.background = drawn.colors.background.with_alpha(0);  // cleared, not painted
  s.scene = make_scene_for(drawn, *pre_pass, s.plan.caption);
  const auto* runs = dynamic_cast<const ComparisonTrajectory*>(pre_pass.get());
  s.plan.csv_name = fs::path(r.output).stem().string() + ".csv";
  if (s.plan.page()) {
    if (runs) s.comparison_plots.emplace(*runs, r.scene.colors.bob);
    else s.page_plots.emplace(pre_pass->info(), page_panel_names(pre_pass->info()), r.scene.name);
    s.csv.emplace(s.staged->path() / s.plan.csv_name, pre_pass->info().columns, r.csv_every);
  }
  HistoryFeed(*pre_pass, *s.scene, s.scene->sample_interval()).record_all([&](std::span<const double> row) {
    if (s.comparison_plots) s.comparison_plots->observe(*runs, row);
    if (s.page_plots) s.page_plots->observe(*pre_pass, row);
    if (s.plan.page()) s.csv->write(pre_pass->index(), pre_pass->done(), row);
  });
}

/// Solve #2, which feeds the frames: the scene sees the history up to each
/// frame's time (moving plots, trails), and frames between steps
/// interpolate the solution (cubic Hermite). A still is drawn now.
void PreparedRender::start_render_pass() {
  State& s = *state_;
  const RenderRequest& r = s.r;
  s.trajectory = build_scene_runs(r.scene);
  s.history.emplace(*s.trajectory, *s.scene, s.scene->sample_interval());
  if (r.at) {
    // The frame that shows the still's time (or would), and its chain's frames before it.
    const FrameClock& clock = *s.plan.clock;
    const long long k = clock.first_frame_from(*r.at);
    const long long d = k < clock.frames() && clock.time(k) == *r.at ? clock.drawn_frame(k) : k;
    auto row_at = [&s](double t) { return s.row_at(t); };
    replay_label_chain(*s.scene, clock, d, r.scene.width, r.scene.height, false, row_at);
    write_still(r, s.plan.target, *s.scene, row_at(*r.at));
    s.done = true;
    return;
  }
  s.canvas.emplace(render::Canvas::image(r.scene.width, r.scene.height));
  s.canvas->track_damage();  // frames redraw, and the encoder converts, only what changed
}

PreparedRender::~PreparedRender() = default;

/// The render's own sinks (files, frames or a stream), their notes told once.
std::unique_ptr<render::FrameSink> PreparedRender::open_sinks() {
  const State& s = *state_;
  const RenderPlan& plan = s.plan;
  const RenderRequest& r = s.r;
  std::map<std::string, std::string> metadata = {{"title", "vibra " + r.scene.name},
                                                 {"comment", render::markup_plain_text(plan.caption)}};
  if (r.segment) metadata["description"] = plan.segment.tag();  // what vibra concat checks
  if (plan.stream()) render::send_standard_output_to(plan.target);  // a pipe or device: written as -o - is
  auto sinks = render::make_frame_sinks(plan.outputs.targets, r.scene.width, r.scene.height, r.scene.fps,
                                        plan.clock->frames(), r.video, metadata, plan.segment.first());
  if (!r.quiet)
    for (const auto& note : sinks->notes()) std::fprintf(stderr, "vibra: %s\n", note.c_str());
  return sinks;
}

/// A page's CSV and HTML written, then its companions and the page put in place together.
void PreparedRender::commit_page() {
  State& s = *state_;
  const RenderPlan& plan = s.plan;
  const RenderRequest& r = s.r;
  const FrameClock& clock = *plan.clock;
  s.csv->commit();
  render::write_text(*s.page_file,
                     page_html(r, plan.outputs, clock, page_facts(r, clock.frames(), *plan.parameters, plan.mesh, plan.speed),
                               s.comparison_plots ? s.comparison_plots->take_panels() : s.page_plots->take_panels(),
                               plan.companions.filename().string() + "/" + plan.csv_name));
  s.staged->seal();
  check_companion_folder(plan.companions, r.force);  // again: the user may have put a file there meanwhile
  // The earlier companions and page go only now, together (the temporaries then hold them, and go).
  render::place_together({{s.staged->path(), plan.companions}, {s.page_file->path(), s.page_file->final_path()}});
}

void PreparedRender::play() {
  State& s = *state_;
  const RenderPlan& plan = s.plan;
  if (s.done) return;
  s.done = true;
  const RenderRequest& r = s.r;
  const FrameClock& clock = *plan.clock;
  const render::FrameSegment& segment = plan.segment;
  Scene& scene = *s.scene;
  render::Canvas& canvas = *s.canvas;
  const bool page = plan.page();
  auto row_at = [&s](double t) { return s.row_at(t); };

  std::unique_ptr<render::FrameSink> own_sink = r.into ? nullptr : open_sinks();
  render::FrameSink* const sink = r.into ? r.into : own_sink.get();
  // A segment's earlier frames are not drawn, but the solver passes through
  // them (moving plots see every step) and the scene keeps up with them, so
  // its frames are the whole render's, byte for byte.
  const long long first_drawn = clock.drawn_frame(segment.first());
  for (long long k = 0; k < first_drawn - first_drawn % kLabelChainFrames; ++k) {
    if ((k & 0xff) == 0) render::throw_if_stop_requested();
    scene.skip(canvas, row_at(clock.time(k)));
  }
  replay_label_chain(scene, clock, first_drawn, r.scene.width, r.scene.height, true, row_at);
  render::Progress progress(r.progress_label, segment.frames(), r.quiet);
  const render::Damage unchanged(r.scene.width, r.scene.height);
  for (long long k = segment.first(); k < segment.end(); ++k) {
    render::throw_if_stop_requested();
    if (k > segment.first() && clock.repeats(k)) {  // a pause: the same picture again, no solver work, no drawing
      sink->write(canvas.data(), canvas.stride(), &unchanged);
      progress.update(k + 1 - segment.first());
      continue;
    }
    canvas.begin_frame();
    scene.set_label_chain((k == segment.first() ? first_drawn : k) / kLabelChainFrames);
    scene.draw(canvas, row_at(clock.time(k)));
    canvas.flush();
    const render::Damage changed = canvas.changed();
    sink->write(canvas.data(), canvas.stride(), &changed);
    progress.update(k + 1 - segment.first());
  }
  if (own_sink) own_sink->finish();
  progress.finish(segment.frames());
  if (page) commit_page();
  if (!r.quiet && r.report_written)
    std::fprintf(stderr, "vibra: wrote %s\n",  // one line, a newline in a file name escaped
                 one_line_message(page ? page_written(r, plan.target, clock.frames()) : sink->description(), 4096).c_str());
}

void run_render(const RenderRequest& r) {
  try {
    PreparedRender(r).play();
  } catch (const render::OutputError& e) {
    throw render::OutputError(render::said_of_output(e.what(), r.output));  // a full disk names OUT, not a temporary
  }
}

}  // namespace vibra::scenes
