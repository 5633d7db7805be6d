#pragma once
#include <span>
#include <string>

#include "core/trajectory.hpp"
#include "render/canvas.hpp"

namespace vibra::scenes {

/// The work an external force has done since t = 0, integrated over the
/// solver steps by the trapezoidal rule from its power F·v, and read between
/// two steps by linear interpolation. A row earlier than the last one fed
/// starts a new pass over the run.
class ForcingWork {
 public:
  void add(double t, double power);
  double at(double t) const;

 private:
  bool started_ = false;
  double t0_ = 0, W0_ = 0;          ///< the step before the newest
  double t1_ = 0, p1_ = 0, W1_ = 0;  ///< the newest step
};

/// Where the energy is: kinetic, potential and dissipated (what drag,
/// friction, dashpots and impacts took out: E(0) + W − E, W the work of an
/// external force), at one row.
struct EnergyBudget {
  double kinetic = 0, potential = 0, dissipated = 0;
};

/// Three vertical bars beside a diagram: kinetic, potential and dissipated
/// energy on one scale fixed over the run by the pre-pass, with the model's
/// energy unit.
class EnergyBars {
 public:
  /// Throws UsageError for a model without a mechanical energy.
  explicit EnergyBars(const TrajectoryInfo&);

  /// The room the bars take beside a diagram, in pixels at this scale.
  static double width(double scale) { return 150 * scale; }

  /// Pre-pass over every solver row: the scale.
  void record(std::span<const double> row);
  /// Every solver step of the render pass: the forcing's work.
  void observe(std::span<const double> row);
  /// The budget at a frame's row (at or before the newest step observed).
  EnergyBudget at(std::span<const double> row) const;
  /// The fixed scale [lo, hi] (after the pre-pass): 0 and every value lie inside.
  double lo() const { return lo_; }
  double hi() const { return hi_; }

  /// Where the bars go (title, bars, labels), at this scale (line widths and fonts).
  void place(const render::PixelRect& area, double scale);
  const render::PixelRect& area() const { return area_; }
  /// The bars at this row inside area(); nothing drawn outside it.
  void draw(render::Canvas&, std::span<const double> row) const;
  /// The pixel rows each bar (kinetic, potential, dissipated) spans at this row.
  struct BarPixels {
    double top[3], bottom[3];
  };
  BarPixels bar_pixels(std::span<const double> row) const;
  /// The rectangle the bars stand in (area() without title and labels).
  render::PixelRect bars_area() const;

 private:
  EnergyBudget budget(std::span<const double> row, const ForcingWork& work) const;
  double pixel_y(const render::PixelRect& bars, double value) const;

  EnergyFunction energy_;
  std::function<double(std::span<const double>)> power_;
  std::string unit_;
  double E0_ = NAN;
  ForcingWork pre_pass_work_, work_;
  double lo_ = 0, hi_ = 0;
  render::PixelRect area_;
  double scale_ = 1;
};

}  // namespace vibra::scenes
