// Energy bars: kinetic, potential, dissipated energy and the work of external forces at one instant.
#pragma once
#include <array>
#include <span>
#include <string>

#include "core/trajectory.hpp"
#include "render/draw/canvas.hpp"
#include "scenes/panels/sample_bracket.hpp"

namespace vibra::scenes {

/// The work an external force has done since t = 0, from its power F·v at
/// the solver steps, streamed in constant memory. Each step is integrated
/// exactly for the cubic through its power and the three samples before it
/// (4th order over the run, like the best schemes, so that a conservative
/// scheme's energy balance holds to its own accuracy rather than to the
/// trapezoidal rule's 2nd order); the first three steps are integrated again
/// with the cubic through the first four samples once the fourth arrives.
/// A row earlier than the last one fed starts a new pass over the run.
class ForcingWork {
 public:
  void add(double t, double power);
  /// The work up to the newest sample.
  double total() const { return W_; }
  /// The work up to t at or after the newest sample, whose power there is
  /// `power` (a frame between steps).
  double at(double t, double power) const;

 private:
  /// The integral from the newest sample to t of the polynomial through the
  /// kept samples and (t, power).
  double beyond_newest(double t, double power) const;

  int kept_ = 0;
  double ts_[4] = {}, ps_[4] = {};  ///< the newest samples, newest last
  bool opening_ = true;             ///< fewer than four samples yet: all are kept from the first
  double W_ = 0;
};

/// Where the energy is: kinetic, potential and dissipated (what drag,
/// friction, dashpots and impacts took out: E(0) + W − E), and the work W an
/// external force has done, at one row: kinetic + potential + dissipated =
/// E(0) + W.
struct EnergyBudget {
  double kinetic = 0, potential = 0, dissipated = 0, work = 0;
};

/// Vertical bars beside a diagram: kinetic, potential and dissipated energy,
/// and with a driving force the work it has done, on one scale fixed over
/// the run by the pre-pass, with the model's energy unit.
class EnergyBars {
 public:
  /// Throws UsageError for a model without a mechanical energy.
  explicit EnergyBars(const TrajectoryInfo&);

  /// The room the bars take beside a diagram, in pixels at this scale: a
  /// fourth bar (the work of a driving force) widens it, so that the labels
  /// under the bars keep apart.
  double width(double scale) const { return (bars() == 4 ? 200 : 150) * scale; }

  /// Pre-pass over every solver row: the scale.
  void record(std::span<const double> row);
  /// Every solver step of the render pass: the forcing's work.
  void observe(std::span<const double> row);
  /// The run's next sample, where it is straight between its samples (Scene::look_ahead).
  void look_ahead(std::span<const std::vector<double>> next_samples);
  /// The budget at a frame's row (at or before the newest step observed);
  /// between two samples of a fixed-step run, each part on the straight line
  /// between its values at them, so the parts still add up to E(0) + W.
  EnergyBudget at(std::span<const double> row) const;
  /// The fixed scale [lo, hi] (after the pre-pass): 0 and every value lie inside.
  double lo() const { return lo_; }
  double hi() const { return hi_; }

  /// Where the bars go (title, bars, labels), at this scale (line widths and fonts).
  void place(const render::PixelRect& area, double scale);
  const render::PixelRect& area() const { return area_; }
  /// The bars at this row inside area(); nothing drawn outside it.
  void draw(render::Canvas&, std::span<const double> row) const;
  /// How many bars: 3, or 4 with the work of a driving force.
  int bars() const { return power_ ? 4 : 3; }
  /// The pixel rows each bar (kinetic, potential, dissipated, work) spans at this row.
  struct BarPixels {
    double top[4], bottom[4];
  };
  BarPixels bar_pixels(std::span<const double> row) const;
  /// The rectangle the bars stand in (area() without title and labels).
  render::PixelRect bars_area() const;

 private:
  EnergyBudget budget(std::span<const double> row, const ForcingWork& work) const;
  /// The budget's values in bar order.
  static std::array<double, 4> values(const EnergyBudget& b) { return {b.kinetic, b.potential, b.dissipated, b.work}; }
  double pixel_y(const render::PixelRect& bars, double value) const;

  EnergyFunction energy_;
  std::function<double(std::span<const double>)> power_;
  std::string unit_;
  double E0_ = NAN;
  ForcingWork pre_pass_work_, work_;
  std::array<SampleBracket, 4> brackets_;  ///< each part at the samples around the frame, in bar order
  double lo_ = 0, hi_ = 0;
  render::PixelRect area_;
  double scale_ = 1;
};

}  // namespace vibra::scenes
