#include "scenes/render_job.hpp"

#include <cairo.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <span>

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
#include "scenes/frame_clock.hpp"
#include "scenes/scene_factory.hpp"

namespace vibra::scenes {

namespace {
std::string extension_of(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(c));
  return ext;
}

std::string caption_of(const SceneConfig& scene, const Parameters& p, const TimeMesh& mesh) {
  std::string caption = scene.model + " · " + std::string(scheme_info(mesh.scheme).name);
  char dt[64];
  std::snprintf(dt, sizeof dt, " · Δ<i>t</i> = %.4g", mesh.dt);
  caption += dt;
  for (const auto& a : p.given_assignments()) {
    const std::string key = a.substr(0, a.find('='));
    if (key != "scheme" && key != "dt" && key != "steps_per_period" && key != "T" && key != "periods")
      caption += " · " + a;
  }
  return caption;
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
  return out;
}

/// Where the frames go: one target, or for a page its videos or frames.
struct Outputs {
  std::vector<std::string> targets;  ///< video files or a frame pattern
  std::string frames_prefix;         ///< player pages: frame name prefix relative to the page
  int digits = 4;
};

Outputs plan_outputs(const RenderRequest& r, long long frames) {
  if (extension_of(r.output) != ".html") return {{r.output}, "", 4};
  const std::filesystem::path page(r.output);
  const std::string stem = page.stem().string();
  if (!r.frames_player) return {{(page.parent_path() / (stem + ".mp4")).string(), (page.parent_path() / (stem + ".webm")).string()}, "", 4};
  const std::filesystem::path directory = page.parent_path() / (stem + "_frames");  // the frame sink creates it
  const render::FramePattern pattern = render::parse_frame_pattern((directory / "frame_%04d.png").string(), frames);
  return {{(directory / "frame_%04d.png").string()}, stem + "_frames/frame_", pattern.digits};
}

void write_page(const RenderRequest& r, const Outputs& outputs, long long frames, const Parameters& p,
                const TimeMesh& mesh) {
  render::PageFacts facts = {{"scene", r.scene.name}, {"model", r.scene.model},
                             {"scheme", std::string(scheme_info(mesh.scheme).name)}};
  char number[64];
  std::snprintf(number, sizeof number, "%.6g", mesh.dt);
  facts.emplace_back("dt", number);
  std::snprintf(number, sizeof number, "%.6g", mesh.T);
  facts.emplace_back("T", number);
  for (const auto& a : p.given_assignments()) facts.emplace_back(a.substr(0, a.find('=')), a.substr(a.find('=') + 1));
  facts.emplace_back("frames", std::to_string(frames) + " at " + std::to_string(int(r.scene.fps)) + " fps");
  facts.emplace_back("made by", "vibra render");
  const std::string title = "vibra: " + r.scene.name;
  std::string html;
  if (r.frames_player) {
    html = render::frames_player_html(title, outputs.frames_prefix, outputs.digits, frames, r.scene.fps, r.scene.width,
                                      r.scene.height, facts);
  } else {
    std::vector<std::string> sources;
    for (const auto& t : outputs.targets) sources.push_back(std::filesystem::path(t).filename().string());
    html = render::video_page_html(title, sources, r.scene.width + (r.scene.width & 1), r.scene.height + (r.scene.height & 1), facts);
  }
  render::write_text_file(r.output, html);
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

  render::start_loading_fonts();  // overlaps the solver's pre-pass and the encoder's start
  const ModelDefinition& model = find_model(r.scene.model);
  const Parameters parameters = model_parameters_of(r.scene);
  std::unique_ptr<Trajectory> pre_pass = model.build(parameters);
  const TimeMesh mesh = pre_pass->info().mesh;
  if (!std::isfinite(mesh.T)) throw UsageError("a render needs a finite end time: give T or periods");
  if (still && (*r.at < 0 || *r.at > mesh.T * (1 + 1e-12)))
    throw UsageError("--at " + std::to_string(*r.at) + " is outside the run [0, " + std::to_string(mesh.T) +
                     "]: choose a time inside it, or a longer T");

  const double speed = r.scene.speed > 0 ? r.scene.speed : (mesh.period > 0 ? mesh.period / 2 : 1);
  const FrameClock clock =
      r.scene.frame_per_step ? FrameClock::per_step(mesh.dt, mesh.steps) : FrameClock::by_speed(mesh.T, r.scene.fps, speed);

  const std::string caption = caption_of(r.scene, parameters, mesh);
  SceneConfig drawn = r.scene;
  if (r.video.transparent) drawn.colors.background = drawn.colors.background.with_alpha(0);  // cleared, not painted
  std::unique_ptr<Scene> scene = make_scene(drawn, pre_pass->info(), caption);

  // Pre-pass: fixed view and plot ranges over the whole run, in constant memory.
  std::vector<double> row(pre_pass->width());
  do {
    pre_pass->row(row);
    scene->record(row);
    if ((pre_pass->index() & 0xfff) == 0) render::throw_if_stop_requested();
  } while (pre_pass->advance());
  pre_pass.reset();

  // The render pass: every solver step feeds the scene (moving plots), and
  // frames between steps interpolate the solution (cubic Hermite).
  std::unique_ptr<Trajectory> trajectory = model.build(parameters);
  std::vector<double> step_row(trajectory->width());
  trajectory->row(step_row);
  scene->observe(step_row);
  auto row_at = [&](double t) {
    while (trajectory->t() < t && trajectory->advance()) {
      trajectory->row(step_row);
      scene->observe(step_row);
    }
    trajectory->row_at(t, row);
    return std::span<const double>(row);
  };
  if (still) return write_still(r, *scene, row_at(*r.at));

  std::map<std::string, std::string> metadata = {{"title", "vibra " + r.scene.name}, {"comment", plain_text(caption)}};
  const Outputs outputs = plan_outputs(r, clock.frames());
  std::vector<std::unique_ptr<render::FrameSink>> sinks;
  for (const auto& target : outputs.targets)
    sinks.push_back(render::make_frame_sink(target, r.scene.width, r.scene.height, r.scene.fps, clock.frames(), r.video,
                                            metadata));
  std::unique_ptr<render::FrameSink> sink =
      sinks.size() == 1 ? std::move(sinks.front()) : render::make_tee_sink(std::move(sinks));
  if (!r.quiet)
    for (const auto& note : sink->notes()) std::fprintf(stderr, "vibra: %s\n", note.c_str());
  render::Canvas canvas = render::Canvas::image(r.scene.width, r.scene.height);
  canvas.track_damage();  // frames redraw, and the encoder converts, only what changed
  render::Progress progress("vibra render", clock.frames(), r.quiet);
  for (long long k = 0; k < clock.frames(); ++k) {
    render::throw_if_stop_requested();
    canvas.begin_frame();
    scene->draw(canvas, row_at(clock.time(k)));
    canvas.flush();
    const render::Damage changed = canvas.changed();
    sink->write(canvas.data(), canvas.stride(), &changed);
    progress.update(k + 1);
  }
  sink->finish();
  progress.finish(clock.frames());
  if (page) write_page(r, outputs, clock.frames(), parameters, mesh);
  if (!r.quiet) std::fprintf(stderr, "vibra: wrote %s\n", (sink->description() + (page ? " and " + r.output : "")).c_str());
}

}  // namespace vibra::scenes
