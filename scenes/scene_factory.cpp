#include "scenes/scene_factory.hpp"

#include "core/error.hpp"
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

  if (!config.panels.empty() && config.layout != Layout::fbd_plot)
    throw UsageError("panels are drawn beside the diagram: use --layout fbd+plot, or drop --panels");
  if (config.energy_bars && config.layout == Layout::plot)
    throw UsageError("energy bars stand beside the diagram: use --layout fbd or fbd+plot, or drop --energy-bars");
  if (config.layout == Layout::plot)
    return std::make_unique<PlotScene>(config.width, config.height, info.mesh.T, style, info.columns[1], info.exact,
                                       info.exact_label);
  const DiagramKind& kind = diagram_for(config);
  const Parameters parameters = model_parameters_of(config);
  std::vector<QuantityPanelSpec> panels;
  for (const auto& name : config.panels)
    panels.push_back(quantity_panel(name, info, config.colors.bob, "", render::palette::vermillion));
  std::unique_ptr<EnergyBars> bars = config.energy_bars ? std::make_unique<EnergyBars>(info) : nullptr;
  return std::make_unique<SystemScene>(config.width, config.height, info, style, kind.make({config, parameters, info}),
                                       std::move(panels), std::move(bars));
}

}  // namespace vibra::scenes
