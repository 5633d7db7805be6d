// LiveScene: one scene solved, recorded and drawn at any time on a recording canvas, as `vibra render --at` draws a still.
#pragma once
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/trajectory.hpp"
#include "render/draw/canvas.hpp"
#include "scenes/config/scene_config.hpp"
#include "scenes/panels/history_feed.hpp"
#include "scenes/scene.hpp"
#include "scenes/timing/frame_clock.hpp"
#include "web/canvas/draw_commands.hpp"

namespace vibra::web {

/// A scene set up as `vibra render SCENE --set KEY=VALUE...` sets it up,
/// whose frame at any time is the still `--at t` draws: the same pre-pass,
/// the same history up to t, the frames of its label chain before it.
class LiveScene {
 public:
  /// Throws UsageError with the CLI's reason for a bad scene, key or value.
  /// `scene` is a built-in scene's or a model's name, or, with `scene_text`
  /// (a scene file's text, carried in the page), that file's name.
  LiveScene(const std::string& scene, const std::vector<std::string>& settings, const std::string& scene_text = "");

  /// Draws the frame at t (0 <= t <= end_time()) into commands(). Playing
  /// forward draws each frame once; a jump back solves the run again.
  /// `whole_chain`: the frames of t's label chain before it are drawn
  /// first, unseen, so that its labels stand where the still's do (up to 89
  /// frames); without, the chain starts at t (a new picture at once, while a
  /// control moves; the page draws the whole chain when it settles).
  void draw(double t, bool whole_chain);
  const DrawCommands& commands() const;
  /// Operations the page's canvas was not handed (web/canvas/surface_commands.hpp).
  int dropped() const;

  double end_time() const { return mesh_.T; }
  int width() const { return config_.width; }
  int height() const { return config_.height; }
  double fps() const { return config_.fps; }
  long long frame_count() const { return clock_->frames(); }
  double frame_time(long long k) const { return clock_->time(k); }

 private:
  /// Solve #2 and a fresh scene: where every draw starts from.
  void start_over();
  /// Draws frame d's label chain before it (nothing of it is kept).
  void replay_chain(long long d);

  scenes::SceneConfig config_;
  TimeMesh mesh_;
  std::string caption_;
  std::optional<scenes::FrameClock> clock_;
  std::unique_ptr<Trajectory> trajectory_;
  std::unique_ptr<scenes::Scene> scene_;
  std::optional<scenes::HistoryFeed> history_;
  std::optional<render::Canvas> canvas_, scratch_;
  long long last_frame_ = -1;
  bool chain_whole_ = false;  ///< the frames of last_frame_'s chain were drawn from its start
  double last_t_ = -1;
};

}  // namespace vibra::web
