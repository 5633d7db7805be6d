#include "scenes/scene_factory.hpp"

#include "scenes/diagram_registry.hpp"
#include "scenes/plot_scene.hpp"
#include "scenes/system_scene.hpp"

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
  const DiagramKind& kind = diagram_for(config);
  const Parameters parameters = model_parameters_of(config);
  return std::make_unique<SystemScene>(config.width, config.height, info.mesh.T, style,
                                       kind.make({config, parameters, info}));
}

}  // namespace vibra::scenes
