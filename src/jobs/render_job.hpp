// The render job: a scene config and model solved and drawn into frames, a video, a still or a page.
#pragma once
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "render/encode/join/frame_segment.hpp"
#include "render/encode/frame_sink.hpp"
#include "core/time_mesh.hpp"
#include "scenes/timing/scene_clock.hpp"
#include "scenes/config/scene_config.hpp"

namespace vibra {
class Trajectory;
}

namespace vibra::scenes {

struct RenderRequest {
  SceneConfig scene;
  std::string output;              ///< video, frame pattern, directory, or a still (.png/.svg/.pdf with `at`)
  std::optional<double> at;        ///< render one still at this time
  render::VideoSettings video;
  /// With -o PAGE.html: PNG frames and a page that steps through them,
  /// instead of PAGE.mp4 + PAGE.webm and a page with a video tag.
  bool frames_player = false;
  /// Render only this segment of the frames (index and count; run_render sets
  /// the total). A video segment goes to segment.file_name(output).
  std::optional<render::FrameSegment> segment;
  /// Do nothing when the output is already complete at its final path.
  bool skip_existing = false;
  /// Replace a page's companion folder, or a segment's file, that vibra did
  /// not write for this output (without it, the run is refused).
  bool force = false;
  /// With -o PAGE.html: the CSV beside the page keeps every K-th step (and the last).
  long long csv_every = 1;
  /// The command that asked for the render, shown on a page.
  std::string command_line;
  bool quiet = false;
  /// What the progress bar calls the work ("vibra render", a lecture's shot name).
  std::string progress_label = "vibra render";
  /// Whether to end with "vibra: wrote ..." (a lecture reports its own output instead).
  bool report_written = true;
  /// Frames go into this sink, left open, instead of one made for `output`
  /// (which still names the kind of output): a lecture's shots share one
  /// encoder, so the encoder starts and drains once, not once a shot.
  render::FrameSink* into = nullptr;
};

/// Solves the scene's model, draws every frame and writes the output. Throws
/// UsageError / SolutionError / OutputError / render::Interrupted; on any of
/// them nothing is left at the output paths, and earlier output there is as
/// it was.
void run_render(const RenderRequest&);

/// A render made ready up to its first frame: checked, solved, its scene laid
/// out and its canvas made (a still is written here, whole). run_render is
/// PreparedRender(r).play(); a lecture prepares a shot on a helper thread
/// while the card before it plays, so the encoder is not kept waiting.
class PreparedRender {
 public:
  /// Throws as run_render does, with nothing written.
  explicit PreparedRender(const RenderRequest&);
  ~PreparedRender();
  PreparedRender(const PreparedRender&) = delete;
  PreparedRender& operator=(const PreparedRender&) = delete;
  /// Draws and writes the frames (once; nothing for a still or a skipped render).
  void play();

 private:
  struct State;
  // The constructor's stages, in order (render_job.cpp).
  void plan_output_kind();
  std::unique_ptr<Trajectory> solve_pre_pass();
  bool check_paths_or_skip();
  void record_pre_pass(std::unique_ptr<Trajectory> pre_pass);
  void start_render_pass();
  // play()'s stages.
  std::unique_ptr<render::FrameSink> open_sinks();
  void commit_page();

  std::unique_ptr<State> state_;
};

/// A page's companions (videos or frames, the CSV, subtitles) go in a
/// folder of their own beside it, PAGE_files/ (as browsers save a page), so
/// the page never writes over a file the user did not name.
std::filesystem::path companion_folder(const std::string& page);

/// A page's companion folder may be replaced when vibra proves it wrote it
/// (its manifest matches), or with `force`; never when it holds a file the
/// run reads, or vibra may not read it. Throws OutputError otherwise.
void check_companion_folder(const std::filesystem::path& folder, bool force);

}  // namespace vibra::scenes
