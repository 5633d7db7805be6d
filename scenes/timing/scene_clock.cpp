// A scene's frame clock and video rate, shared by renders, lectures and the browser's live page.
#include "scenes/timing/scene_clock.hpp"

namespace vibra::scenes {

double steady_speed(const SceneConfig& scene, const TimeMesh& mesh) {
  return scene.speed > 0 ? scene.speed : (mesh.period > 0 ? mesh.period / 2 : 1);
}

double video_rate_of(const SceneConfig& scene, const TimeMesh& mesh) {
  return scene.frame_per_step ? mesh.dt * scene.fps : steady_speed(scene, mesh);
}

FrameClock frame_clock_of(const SceneConfig& scene, const TimeMesh& mesh) {
  if (!scene.frame_per_step) return FrameClock::paced(mesh.T, scene.fps, steady_speed(scene, mesh), scene.pacing);
  if (scene.pacing.empty()) return FrameClock::per_step(mesh.dt, mesh.steps);
  return FrameClock::paced(double(mesh.steps) * mesh.dt, scene.fps, video_rate_of(scene, mesh), scene.pacing);
}

}  // namespace vibra::scenes
