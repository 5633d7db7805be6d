// LiveScene: the render job's pre-pass, render pass and still drawn again for the page, on a canvas that records operations.
#include "web/live_scene.hpp"

#include <cmath>

#include "core/comparison_trajectory.hpp"
#include "core/error.hpp"
#include "scenes/diagrams/comparison_labels.hpp"
#include "scenes/overlays/run_caption.hpp"
#include "scenes/scene_factory.hpp"
#include "scenes/timing/scene_clock.hpp"
#include "web/canvas/surface_commands.hpp"

namespace vibra::web {

namespace {

/// One "KEY=VALUE" as `--set` takes it; the CLI's reason when it is not one.
scenes::Setting setting_of(const std::string& text) {
  const auto eq = text.find('=');
  if (eq == std::string::npos || eq == 0)
    throw UsageError("--set " + text + ": expected KEY=VALUE, e.g. --set Theta=60");
  return {text.substr(0, eq), text.substr(eq + 1), "--set"};
}

/// The caption a render of this run shows, as the render job writes it.
std::string caption_of(const scenes::SceneConfig& config, const Trajectory& runs) {
  if (const auto* compared = dynamic_cast<const ComparisonTrajectory*>(&runs))
    return scenes::comparison_caption(config.model, compared->comparison());
  return scenes::run_caption(config.model, scenes::model_parameters_of(config), runs.info().mesh);
}

}  // namespace

LiveScene::LiveScene(const std::string& scene, const std::vector<std::string>& settings,
                     const std::string& scene_text)
    : config_(scene_text.empty() ? scenes::load_scene(scene) : scenes::parse_scene(scene_text, scene)) {
  for (const std::string& s : settings) scenes::apply_setting(config_, setting_of(s));
  const std::unique_ptr<Trajectory> runs = scenes::build_scene_runs(config_);
  mesh_ = runs->info().mesh;
  if (!std::isfinite(mesh_.T)) throw UsageError("a render needs a finite end time: give T or periods");
  clock_.emplace(scenes::frame_clock_of(config_, mesh_));
  caption_ = caption_of(config_, *runs);
  // The page draws in the browser's canvas: a vector surface, whose
  // operations are handed over, never a file.
  canvas_.emplace(render::Canvas::svg("", config_.width, config_.height));
  scratch_.emplace(render::Canvas::svg("", config_.width, config_.height));
  start_over();
}

void LiveScene::start_over() {
  history_.reset();
  const std::unique_ptr<Trajectory> pre_pass = scenes::build_scene_runs(config_);
  scene_ = scenes::make_scene_for(config_, *pre_pass, caption_);
  scenes::HistoryFeed(*pre_pass, *scene_, scene_->sample_interval()).record_all([](auto) {});
  trajectory_ = scenes::build_scene_runs(config_);
  history_.emplace(*trajectory_, *scene_, scene_->sample_interval());
  last_frame_ = -1;
  last_t_ = -1;
}

void LiveScene::replay_chain(long long d) {
  // As a still does (src/jobs/render_job.cpp): the frames of d's chain
  // before it, drawn where nothing is kept, so its labels keep their spots.
  const long long start = std::max(d - d % scenes::kLabelChainFrames, last_frame_ + 1);
  for (long long j = start; j < d; ++j) {
    if (clock_->repeats(j)) continue;
    scene_->draw(*scratch_, history_->row_at(clock_->time(j)));
    commands_of(scratch_->surface()).clear();
  }
}

void LiveScene::draw(double t, bool whole_chain) {
  if (!(t >= 0 && t <= mesh_.T * (1 + 1e-12)))
    throw UsageError("t = " + std::to_string(t) + " is outside the run [0, " + std::to_string(mesh_.T) + "]");
  const long long k = clock_->first_frame_from(t);
  const long long d = k < clock_->frames() && clock_->time(k) == t ? clock_->drawn_frame(k) : k;
  constexpr long long kChain = scenes::kLabelChainFrames;
  const bool same_chain = last_frame_ >= 0 && d / kChain == last_frame_ / kChain;
  // The scene has seen the history up to the last time; and a chain begun
  // part way (a control moved) holds its labels' spots from there, so the
  // still's whole chain is drawn afresh.
  if (t < last_t_ || (same_chain && whole_chain && !chain_whole_)) start_over();
  if (last_frame_ < 0 || d / kChain != last_frame_ / kChain) {
    chain_whole_ = whole_chain;
    last_frame_ = whole_chain ? d - d % kChain - 1 : d - 1;
  }
  scene_->set_label_chain(d / kChain);
  replay_chain(d);
  commands_of(canvas_->surface()).clear();
  scene_->draw(*canvas_, history_->row_at(t));
  last_frame_ = d;
  last_t_ = t;
}

const DrawCommands& LiveScene::commands() const { return commands_of(canvas_->surface()); }
int LiveScene::dropped() const { return skipped_of(canvas_->surface()); }

}  // namespace vibra::web
