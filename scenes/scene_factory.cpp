#include "scenes/scene_factory.hpp"

#include "core/error.hpp"
#include "scenes/pendulum_scene.hpp"
#include "scenes/plot_scene.hpp"

namespace vibra::scenes {

std::unique_ptr<Scene> make_scene(const SceneConfig& config, const TrajectoryInfo& info, const std::string& caption) {
  SceneStyle style;
  style.layout = config.layout;
  style.colors = config.colors;
  style.period = info.mesh.period;
  style.caption = caption;
  style.window = window_width(config, info.mesh.period);
  style.window_mode = style.window > 0 ? config.window_mode : WindowMode::whole_run;
  if (style.window > 0 && style.window >= info.mesh.T) style.window_mode = WindowMode::whole_run;

  if (config.layout == Layout::plot)
    return std::make_unique<PlotScene>(config.width, config.height, info.mesh.T, style, info.columns[1], info.exact,
                                       info.exact_label);
  if (config.model != "pendulum" && config.model != "physical-pendulum")
    throw UsageError("model " + config.model + " has no free-body diagram: use --layout plot (pendulum and "
                     "physical-pendulum have diagrams)");
  PendulumDiagramOptions diagram;
  diagram.drag_magnification = config.drag_magnification;
  return std::make_unique<PendulumScene>(config.width, config.height, info.mesh.T, style, diagram);
}

}  // namespace vibra::scenes
