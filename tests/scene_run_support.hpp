// A scene fed as the render job feeds it, for tests that look at the frame of a given moment without writing files.
#pragma once
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

}  // namespace vibra::test
