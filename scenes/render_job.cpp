#include "scenes/render_job.hpp"

#include <cairo.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <span>

#include "core/comparison_trajectory.hpp"
#include "core/error.hpp"
#include "core/models/model.hpp"
#include "render/canvas.hpp"
#include "render/html_page.hpp"
#include "render/png_sequence.hpp"
#include "render/output_error.hpp"
#include "render/progress.hpp"
#include "render/stop_signal.hpp"
#include "render/temporary_file.hpp"
#include "render/text.hpp"
#include "render/video_concat.hpp"
#include "scenes/frame_clock.hpp"
#include "scenes/history_feed.hpp"
#include "scenes/comparison_labels.hpp"
#include "scenes/comparison_page_plots.hpp"
#include "scenes/page_plot_collector.hpp"
#include "scenes/run_caption.hpp"
#include "scenes/run_csv_file.hpp"
#include "scenes/scene_factory.hpp"

namespace vibra::scenes {

namespace {
std::string extension_of(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(c));
  return ext;
}

/// Pango markup without its tags, for file metadata.
std::string plain_text(const std::string& markup) {
  std::string out;
  bool in_tag = false;
  for (char c : markup) {
    if (c == '<') in_tag = true;
    else if (c == '>') in_tag = false;
    else if (!in_tag) out += c;
  }
  // The entities run_caption escapes, back to their characters.
  for (const auto& [entity, c] : {std::pair{"&lt;", '<'}, {"&gt;", '>'}, {"&amp;", '&'}})
    for (size_t at = 0; (at = out.find(entity, at)) != std::string::npos; ++at)
      out.replace(at, std::string_view(entity).size(), 1, c);
  return out;
}

/// A hash (FNV-1a) of everything that shapes a render's frames and their
/// coding, so that segments of different renders are told apart. Threads are
/// left out: they change how fast, not what.
std::uint64_t render_fingerprint(const RenderRequest& r, const std::string& caption, long long frames) {
  const SceneConfig& c = r.scene;
  std::string text = c.name + '\n' + c.model + '\n' + caption + '\n';
  for (const auto& s : c.model_settings) text += s.key + '=' + s.value + '\n';
  if (!c.compare.empty()) text += "compare " + c.compare + '\n';
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
          r.video.preset + (r.video.transparent ? "\ntransparent" : "");
  std::uint64_t hash = 14695981039346656037ull;
  for (unsigned char byte : text) hash = (hash ^ byte) * 1099511628211ull;
  return hash;
}

/// Where the frames go: one target, or for a page its videos or frames.
struct Outputs {
  std::vector<std::string> targets;  ///< video files or a frame pattern
  std::string frames_prefix;         ///< player pages: frame name prefix relative to the page
  int digits = 4;
};

Outputs plan_outputs(const RenderRequest& r, const render::FrameSegment& segment) {
  const long long frames = segment.total;
  if (r.segment && render::is_video_path(r.output)) return {{segment.file_name(r.output)}, "", 4};
  if (extension_of(r.output) != ".html") return {{r.output}, "", 4};
  const std::filesystem::path page(r.output);
  const std::string stem = page.stem().string();
  if (!r.frames_player) return {{(page.parent_path() / (stem + ".mp4")).string(), (page.parent_path() / (stem + ".webm")).string()}, "", 4};
  const std::filesystem::path directory = page.parent_path() / (stem + "_frames");  // the frame sink creates it
  const render::FramePattern pattern = render::parse_frame_pattern((directory / "frame_%04d.png").string(), frames);
  return {{(directory / "frame_%04d.png").string()}, stem + "_frames/frame_", pattern.digits};
}

/// --skip-existing: whether the outputs are complete at their final paths.
/// Outputs are renamed into place only when complete, so existence is proof;
/// a segment video must also hold this segment (not one of another split).
bool already_complete(const RenderRequest& r, const Outputs& outputs, const render::FrameSegment& segment) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (r.at || extension_of(r.output) == ".html") return fs::exists(r.output, ec);
  const std::string& target = outputs.targets.front();
  if (render::is_video_path(target))
    return fs::exists(target, ec) && (!r.segment || render::read_segment_tag(target) == segment);
  const render::FramePattern pattern = render::parse_frame_pattern(target, segment.total);
  for (long long k = segment.first(); k < segment.end(); ++k)
    if (!fs::exists(pattern.name(k), ec)) return false;
  return true;
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
  facts.emplace_back("size", std::to_string(r.scene.width) + "x" + std::to_string(r.scene.height));
  return facts;
}

/// A page beside its videos (or frames) and CSV, with the run's time series.
void write_page(const RenderRequest& r, const Outputs& outputs, const FrameClock& clock, render::PageFacts facts,
                std::vector<render::PagePanel> panels, const std::string& csv_name) {
  render::LecturePage page;
  page.title = "vibra: " + r.scene.name;
  render::PageMedia& media = page.media;
  media.width = r.scene.width + (r.scene.width & 1);  // videos are even-sized
  media.height = r.scene.height + (r.scene.height & 1);
  media.frames = clock.frames();
  media.fps = r.scene.fps;
  media.frame_interval = clock.interval();
  if (r.frames_player) {
    media.kind = render::PageMedia::Kind::frames;
    media.frames_prefix = outputs.frames_prefix;
    media.digits = outputs.digits;
    media.width = r.scene.width, media.height = r.scene.height;
  } else {
    media.kind = render::PageMedia::Kind::video;
    for (const auto& t : outputs.targets) {
      const std::string name = std::filesystem::path(t).filename().string();
      media.videos.push_back(name);
      page.downloads.push_back({extension_of(name) == ".mp4" ? "MP4 video" : "WebM video", name});
    }
  }
  page.downloads.push_back({"CSV of the run", csv_name});
  page.panels = std::move(panels);
  page.facts = std::move(facts);
  page.command_line = r.command_line;
  render::write_text_file(r.output, render::lecture_page_html(page));
}

/// Writes one picture at the request's time: PNG, SVG or PDF.
void write_still(const RenderRequest& r, Scene& scene, std::span<const double> row) {
  const std::string ext = extension_of(r.output);
  render::TemporaryFile file(r.output);
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
  if (!r.quiet) std::fprintf(stderr, "vibra: wrote %s (t = %g)\n", r.output.c_str(), row[0]);
}
}  // namespace

void run_render(const RenderRequest& r) {
  const std::string ext = extension_of(r.output);
  const bool still = r.at.has_value();
  if (still && !std::isfinite(*r.at))
    throw UsageError("--at " + std::string(std::isnan(*r.at) ? "nan" : "inf") +
                     " is not a time: give a finite time inside the run, e.g. --at 3.2");
  if (still && ext != ".png" && ext != ".svg" && ext != ".pdf")
    throw UsageError("--at renders one still: give -o FILE.png, FILE.svg or FILE.pdf");
  if (!still && (ext == ".svg" || ext == ".pdf"))
    throw UsageError("-o " + r.output + " is one picture: add --at T to choose its time");
  const bool page = ext == ".html", stream = r.output == "-";
  if (r.frames_player && !page) throw UsageError("--frames-player writes a page: give -o PLAYER.html");
  if (r.csv_every < 1) throw UsageError("--every must be at least 1: the page's CSV keeps every K-th step");
  if (r.csv_every != 1 && !page) throw UsageError("--every thins the CSV beside a page: give -o PAGE.html, or drop --every");
  if (r.video.transparent && page && !r.frames_player)
    throw UsageError("a page's MP4 cannot be transparent: add --frames-player (PNG frames), or write .webm or .mov");
  render::check_output_settings(r.output, r.video);
  if (!still && !page && !stream && !render::is_video_path(r.output) && !render::is_frame_pattern(r.output)) {
    if (ext == ".png")
      throw UsageError("-o " + r.output + " is one picture: add --at T, or give a pattern such as frames/tmp_%04d.png");
    throw UsageError("cannot tell what to write from -o " + r.output +
                     ": use .mp4, .webm, .mkv, .mov, .ogv, .gif, .yuv, .html, a frame pattern frames/tmp_%04d.png, a "
                     "directory, - (standard output) with --format, or .png/.svg/.pdf with --at");
  }

  if (r.segment) {
    if (still) throw UsageError("--segment splits a video or frame sequence; --at renders one still: drop one of them");
    if (stream)
      throw UsageError("--segment writes files for vibra concat to join: give -o FILE.mp4, .mkv, .webm or PNG frames, "
                       "not - (standard output)");
    if (page)
      throw UsageError("--segment cannot split a page (.html): render segments to .mp4, .mkv, .webm or PNG frames, "
                       "join them with vibra concat");
    if (render::is_video_path(r.output) && ext != ".mp4" && ext != ".mkv" && ext != ".webm")
      throw UsageError("--segment needs a video that keeps timestamps: write .mp4, .mkv or .webm (or PNG frames), "
                       "not " + ext);
  }

  render::start_loading_fonts();  // overlaps the solver's pre-pass and the encoder's start
  // A comparison's runs go through the render as one trajectory of wide rows.
  const Parameters parameters =
      r.scene.compare.empty() ? model_parameters_of(r.scene)
                              : comparison_base_of(r.scene, parse_comparison(r.scene.compare).key);
  std::unique_ptr<Trajectory> pre_pass = build_scene_runs(r.scene);
  const TimeMesh mesh = pre_pass->info().mesh;
  if (!std::isfinite(mesh.T)) throw UsageError("a render needs a finite end time: give T or periods");
  if (still && (*r.at < 0 || *r.at > mesh.T * (1 + 1e-12)))
    throw UsageError("--at " + std::to_string(*r.at) + " is outside the run [0, " + std::to_string(mesh.T) +
                     "]: choose a time inside it, or a longer T");

  const double speed = r.scene.speed > 0 ? r.scene.speed : (mesh.period > 0 ? mesh.period / 2 : 1);
  const FrameClock clock =
      r.scene.frame_per_step ? FrameClock::per_step(mesh.dt, mesh.steps) : FrameClock::by_speed(mesh.T, r.scene.fps, speed);
  const auto* runs = dynamic_cast<const ComparisonTrajectory*>(pre_pass.get());
  const std::string caption =
      runs ? comparison_caption(r.scene.model, runs->comparison()) : run_caption(r.scene.model, parameters, mesh);
  render::FrameSegment segment{0, 1, clock.frames()};
  if (r.segment) {
    segment = {r.segment->index, r.segment->count, clock.frames(), render_fingerprint(r, caption, clock.frames())};
    if (segment.frames() == 0)
      throw UsageError("segment " + std::to_string(segment.index) + "/" + std::to_string(segment.count) +
                       " has no frames: the render has only " + std::to_string(segment.total) +
                       ", so use at most that many segments");
  }
  const Outputs outputs = still ? Outputs{} : plan_outputs(r, segment);
  if (r.skip_existing && already_complete(r, outputs, segment)) {
    const std::string& done = page || still ? r.output : outputs.targets.front();
    if (!r.quiet) std::fprintf(stderr, "vibra: %s is already complete: skipped\n", done.c_str());
    return;
  }

  SceneConfig drawn = r.scene;
  if (r.video.transparent) drawn.colors.background = drawn.colors.background.with_alpha(0);  // cleared, not painted
  std::unique_ptr<Scene> scene = make_scene_for(drawn, *pre_pass, caption);

  // Pre-pass: fixed view and plot ranges over the whole run, in constant
  // memory; for a page also its time series and its CSV.
  std::optional<PagePlotCollector> page_plots;
  std::optional<ComparisonPagePlots> comparison_plots;  // a comparison's page: a curve per member
  std::optional<RunCsvFile> csv;
  const std::filesystem::path csv_path = std::filesystem::path(r.output).replace_extension(".csv");
  if (page) {
    if (runs) comparison_plots.emplace(*runs, r.scene.colors.bob);
    else page_plots.emplace(pre_pass->info(), page_panel_names(pre_pass->info()), r.scene.name);
    csv.emplace(csv_path, pre_pass->info().columns, r.csv_every);
  }
  HistoryFeed(*pre_pass, *scene, scene->sample_interval()).record_all([&](std::span<const double> row) {
    if (comparison_plots) comparison_plots->observe(*runs, row);
    if (page_plots) page_plots->observe(row);
    if (page) csv->write(pre_pass->index(), pre_pass->done(), row);
  });
  pre_pass.reset();
  runs = nullptr;  // it was the pre-pass

  // The render pass: the scene sees the history up to each frame's time
  // (moving plots, trails), and frames between steps interpolate the
  // solution (cubic Hermite).
  std::unique_ptr<Trajectory> trajectory = build_scene_runs(r.scene);
  HistoryFeed history(*trajectory, *scene, scene->sample_interval());
  auto row_at = [&](double t) { return history.row_at(t); };
  if (still) return write_still(r, *scene, row_at(*r.at));

  std::map<std::string, std::string> metadata = {{"title", "vibra " + r.scene.name}, {"comment", plain_text(caption)}};
  if (r.segment) metadata["description"] = segment.tag();  // what vibra concat checks
  std::vector<std::unique_ptr<render::FrameSink>> sinks;
  for (const auto& target : outputs.targets)
    sinks.push_back(render::make_frame_sink(target, r.scene.width, r.scene.height, r.scene.fps, clock.frames(), r.video,
                                            metadata, segment.first()));
  std::unique_ptr<render::FrameSink> sink =
      sinks.size() == 1 ? std::move(sinks.front()) : render::make_tee_sink(std::move(sinks));
  if (!r.quiet)
    for (const auto& note : sink->notes()) std::fprintf(stderr, "vibra: %s\n", note.c_str());
  render::Canvas canvas = render::Canvas::image(r.scene.width, r.scene.height);
  canvas.track_damage();  // frames redraw, and the encoder converts, only what changed
  // A segment's earlier frames are not drawn, but the solver passes through
  // them (moving plots see every step) and the scene keeps up with them, so
  // its frames are the whole render's, byte for byte.
  for (long long k = 0; k < segment.first(); ++k) {
    if ((k & 0xff) == 0) render::throw_if_stop_requested();
    scene->skip(canvas, row_at(clock.time(k)));
  }
  render::Progress progress("vibra render", segment.frames(), r.quiet);
  for (long long k = segment.first(); k < segment.end(); ++k) {
    render::throw_if_stop_requested();
    canvas.begin_frame();
    scene->draw(canvas, row_at(clock.time(k)));
    canvas.flush();
    const render::Damage changed = canvas.changed();
    sink->write(canvas.data(), canvas.stride(), &changed);
    progress.update(k + 1 - segment.first());
  }
  sink->finish();
  progress.finish(segment.frames());
  if (page) {
    csv->commit();
    write_page(r, outputs, clock, page_facts(r, clock.frames(), parameters, mesh, speed),
               comparison_plots ? comparison_plots->take_panels() : page_plots->take_panels(),
               csv_path.filename().string());
  }
  if (!r.quiet) std::fprintf(stderr, "vibra: wrote %s\n", (sink->description() + (page ? " and " + r.output : "")).c_str());
}

}  // namespace vibra::scenes
