#pragma once
#include <Eigen/Geometry>
#include <optional>
#include <string>
#include <vector>

#include "render/canvas.hpp"
#include "scenes/pendulum_geometry.hpp"
#include "scenes/scene.hpp"
#include "scenes/series_panel.hpp"
#include "scenes/static_layer.hpp"

namespace vibra::scenes {

enum class Layout { fbd, fbd_plot, plot };

/// Colours of the diagram; scene files may override each.
struct PendulumColors {
  render::Color background = render::palette::paper;
  render::Color bob = render::palette::blue;
  render::Color wire = render::palette::ink;
  render::Color gravity = render::palette::vermillion;
  render::Color wire_force = render::palette::green;
  render::Color drag = render::palette::purple;
};

/// What every scene shares: layout, colours, the plots' window, the
/// read-out of time.
struct SceneStyle {
  Layout layout = Layout::fbd_plot;
  PendulumColors colors;
  WindowMode window_mode = WindowMode::whole_run;
  double window = 0;         ///< window width in time units (window modes)
  double period = 2 * M_PI;  ///< for the read-out "t = ... (n periods)"; 0 = none
  std::string caption;       ///< a line of parameters at the bottom (Pango markup)
};

/// The pendulum's free-body diagram (SPEC 8.1), alone or beside stacked
/// panels of theta, S and D against time with a cursor at the current time.
/// Rows are the pendulum model's: t, theta, omega, S, D. The diagram's view is
/// fixed over the run (from the pre-pass), so nothing jumps and nothing is
/// clipped at the largest angle.
class PendulumScene final : public Scene {
 public:
  PendulumScene(int width, int height, double t_end, SceneStyle, PendulumDiagramOptions);

  void record(std::span<const double> row) override;
  void observe(std::span<const double> row) override;
  void draw(render::Canvas&, std::span<const double> row) override;
  void skip(const render::Canvas&, std::span<const double> row) override;

  /// The diagram's world box over the run (after record()).
  const Eigen::AlignedBox2d& world_box() const { return world_; }

 private:
  void prepare();
  void draw_static(render::Canvas&);
  void draw_diagram(render::Canvas&, const PendulumState&);
  /// The curves drawn so far, for the layer under frame time t.
  StaticLayer::Grow progress_to(double t);

  int height_;
  SceneStyle style_;
  PendulumDiagramOptions diagram_;
  render::PixelRect diagram_area_;
  std::vector<SeriesPanel> panels_;
  Eigen::AlignedBox2d world_;
  std::optional<render::WorldView> view_;
  StaticLayer background_;
};

/// Draws the time read-out and the caption common to every scene.
void draw_readout(render::Canvas&, const render::PixelRect& area, double t, const SceneStyle&);

}  // namespace vibra::scenes
