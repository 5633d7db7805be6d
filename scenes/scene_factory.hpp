#pragma once
#include <memory>
#include <string>

#include "core/trajectory.hpp"
#include "scenes/scene.hpp"
#include "scenes/scene_config.hpp"

namespace vibra::scenes {

/// The scene a config asks for, for a run described by `info`: the pendulum's
/// free-body diagram (pendulum models, layouts fbd and fbd+plot), or the
/// moving plot of the main quantity (layout plot, any model). Throws
/// UsageError for a diagram of a model that has none.
std::unique_ptr<Scene> make_scene(const SceneConfig&, const TrajectoryInfo& info, const std::string& caption);

}  // namespace vibra::scenes
