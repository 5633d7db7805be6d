#pragma once
#include <functional>
#include <string>

#include "scenes/scene.hpp"
#include "scenes/scene_style.hpp"
#include "scenes/series_panel.hpp"
#include "scenes/static_layer.hpp"

namespace vibra::scenes {

/// Any model's main quantity against time in one panel, with the exact
/// solution dashed where it is known: the moving plot of a long run.
class PlotScene final : public Scene {
 public:
  /// `quantity` is the main column's name (e.g. "u", "theta"); `exact` may be empty.
  PlotScene(int width, int height, double t_end, SceneStyle, const std::string& quantity,
            std::function<double(double)> exact, const std::string& exact_label);

  void record(std::span<const double> row) override { panel_.record(row); }
  void observe(std::span<const double> row) override { panel_.observe(row); }
  void draw(render::Canvas&, std::span<const double> row) override;

 private:
  SceneStyle style_;
  render::PixelRect area_;
  SeriesPanel panel_;
  StaticLayer background_;
  bool prepared_ = false;
};

}  // namespace vibra::scenes
