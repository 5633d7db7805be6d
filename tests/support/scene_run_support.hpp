// A scene fed as the render job feeds it, for tests that look at the frame of a given moment without writing files.
#pragma once
#include <cmath>
#include <memory>
#include <vector>

#include "scenes/scene.hpp"
#include "scenes/scene_factory.hpp"

namespace vibra::test {

/// A scene of `config` after its pre-pass over every solver row (the row
/// count in `steps`), ready to observe and draw from the first row.
inline std::unique_ptr<scenes::Scene> scene_after_pre_pass(const scenes::SceneConfig& config, long long& steps) {
  auto pre_pass = scenes::build_scene_runs(config);
  auto scene = scenes::make_scene_for(config, *pre_pass, "a test");
  std::vector<double> row(pre_pass->width());
  steps = 0;
  do {
    pre_pass->row(row);
    scene->record(row);
    ++steps;
  } while (pre_pass->advance());
  return scene;
}

/// The row at `moment` of `config`'s run (0 = the first row, 1 = the last),
/// with `scene` (after its pre-pass of `steps` rows) having observed every
/// row up to it, as the render job feeds a scene before drawing that frame.
inline std::vector<double> observed_row_at(scenes::Scene& scene, const scenes::SceneConfig& config, long long steps,
                                           double moment) {
  const long long wanted = std::llround(moment * double(steps - 1));
  auto runs = scenes::build_scene_runs(config);
  std::vector<double> row(runs->width());
  for (long long step = 0;; ++step) {
    runs->row(row);
    scene.observe(row);
    if (step == wanted || !runs->advance()) break;
  }
  return row;
}

}  // namespace vibra::test
