#pragma once
#include <memory>
#include <string>

#include "core/trajectory.hpp"
#include "scenes/scene.hpp"
#include "scenes/scene_config.hpp"

namespace vibra::scenes {

/// The scene a config asks for, for a run described by `info`: the system's
/// diagram (layouts fbd and fbd+plot; the scene's `diagram`, or the model's
/// default from the diagram registry), or the moving plot of the main
/// quantity (layout plot, any model). Throws UsageError for a diagram of a
/// model that has none.
std::unique_ptr<Scene> make_scene(const SceneConfig&, const TrajectoryInfo& info, const std::string& caption);

}  // namespace vibra::scenes
