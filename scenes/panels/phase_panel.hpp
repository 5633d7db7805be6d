// PhasePanel: the phase plane of a run, fixed ranges from the pre-pass and a trail.
#pragma once
#include <deque>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "render/plot/plot_panel.hpp"
#include "scenes/panels/scene_panel.hpp"

namespace vibra::scenes {

/// One curve of a phase-plane panel: a point (x, y) computed from a solution
/// row (t first), e.g. the velocity and the main quantity.
struct PhaseCurveSpec {
  std::string label;  ///< legend text (Pango markup); "" = no legend entry
  render::Color color;
  std::function<double(std::span<const double> row)> x, y;
};

/// The phase plane: each curve's current point and a trail of its recent
/// past that fades with age, on ranges fixed by the pre-pass (so a scheme
/// that spirals out or in shows it against fixed axes). The same in every
/// window mode: it has no time axis. Memory per curve is a fixed number of
/// trail points, whatever the run.
class PhasePanel final : public ScenePanel {
 public:
  /// `trail` is how far back the trail reaches, in time units.
  PhasePanel(const render::PixelRect& outer, double scale, std::string x_label, std::string y_label,
             std::vector<PhaseCurveSpec> curves, double trail);

  void record(std::span<const double> row) override;
  void observe(std::span<const double> row) override;
  void finish_recording() override;
  /// Both axes get the same pixels per unit (set before finish_recording):
  /// a circle in the data is a circle on screen.
  void keep_equal_scales() { equal_scales_ = true; }
  bool against_time() const override { return false; }
  void draw_static(render::Canvas&, bool time_labels) const override;
  void draw(render::Canvas&, double t, std::span<const double> row, bool time_labels) const override;

  /// Trail points kept per curve at most.
  static constexpr size_t kTrailPoints = 400;
  size_t trail_size(size_t curve) const { return trails_[curve].size(); }
  /// The fixed horizontal range (after finish_recording), and where a point is drawn.
  std::pair<double, double> x_range() const { return {panel_.x0(), panel_.x1()}; }
  render::Point pixel_of(double x, double y) const { return panel_.to_pixel(x, y); }

 private:
  struct TrailPoint {
    double t, x, y;
  };

  render::PlotPanel panel_;
  std::string x_label_, y_label_;
  std::vector<PhaseCurveSpec> curves_;
  double trail_;
  std::vector<std::deque<TrailPoint>> trails_;
  double x_lo_ = 1e300, x_hi_ = -1e300, y_lo_ = 1e300, y_hi_ = -1e300;
  bool equal_scales_ = false;
};

}  // namespace vibra::scenes
