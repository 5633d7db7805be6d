#pragma once
#include <optional>
#include <string>

#include "render/encode/frame_segment.hpp"
#include "render/encode/frame_sink.hpp"
#include "scenes/scene_config.hpp"

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
};

/// Solves the scene's model, draws every frame and writes the output. Throws
/// UsageError / SolutionError / OutputError / render::Interrupted; on any of
/// them nothing is left at the output paths, and earlier output there is as
/// it was.
void run_render(const RenderRequest&);

}  // namespace vibra::scenes
