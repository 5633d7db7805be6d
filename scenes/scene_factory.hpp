// Picks and builds the scene a config asks for: a system's diagram with panels, or plots alone.
#pragma once
#include <memory>
#include <string>

#include "core/comparison_trajectory.hpp"
#include "core/trajectory.hpp"
#include "scenes/scene.hpp"
#include "scenes/config/scene_config.hpp"

namespace vibra::scenes {

/// The scene a config asks for, for a run described by `info`: the system's
/// diagram (layouts fbd and fbd+plot; the scene's `diagram`, or the model's
/// default from the diagram registry), or the moving plot of the main
/// quantity (layout plot, any model). Throws UsageError for a diagram of a
/// model that has none.
std::unique_ptr<Scene> make_scene(const SceneConfig&, const TrajectoryInfo& info, const std::string& caption);

/// The runs a scene draws: its model's run, or with `compare` one run per
/// value as a ComparisonTrajectory. Throws UsageError for bad settings.
std::unique_ptr<Trajectory> build_scene_runs(const SceneConfig&);

/// make_scene or make_comparison_scene, whichever `runs` (from build_scene_runs) needs.
std::unique_ptr<Scene> make_scene_for(const SceneConfig&, const Trajectory& runs, const std::string& caption);

/// The scene of a comparison, fed the rows of `runs`: the members' diagrams
/// (the first solid, the others as ghosts) beside panels with a curve per
/// member (fbd, fbd+plot); the main quantity of every member in one panel
/// (plot); or a panel per member on one time axis (grid). A legend names the
/// members. Throws UsageError as make_scene does.
std::unique_ptr<Scene> make_comparison_scene(const SceneConfig&, const ComparisonTrajectory& runs,
                                             const std::string& caption);

}  // namespace vibra::scenes
