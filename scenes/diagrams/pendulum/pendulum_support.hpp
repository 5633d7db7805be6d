// What a pendulum hangs from: a ceiling while its recorded motion stays below it, else a bearing block nothing reaches.
#pragma once
#include "render/draw/canvas.hpp"
#include "scenes/diagrams/diagram.hpp"

namespace vibra::scenes {

/// The support of a pendulum whose pivot is at `pivot` (docs/drawing.md).
/// The pre-pass shows it every drawn bob (a disc); after it, a ceiling is
/// kept when every bob stays clear below the ceiling line, else the pivot is
/// a bearing block seen from behind, small enough that no bob ever drawn
/// reaches it: a pendulum going over the top, or an elastic one flung above
/// its pivot, would otherwise pass through the hatched ceiling.
class PendulumSupport {
 public:
  static constexpr double kCeilingHalfWidth = 0.3;  ///< in units of the wire's length
  /// The ceiling's hatching and line stand about 12 px above the line: a bob
  /// this close under it (a tenth of the wire) would touch them.
  static constexpr double kCeilingClearance = 0.1;
  static constexpr double kLargestBlock = 0.07;  ///< the block's half side when there is room

  explicit PendulumSupport(const Point& pivot) : pivot_(pivot) {}

  /// A bob of radius r drawn at `center` in some frame of the run.
  void see(const Point& center, double r);
  bool is_ceiling() const { return highest_ < pivot_.y() - kCeilingClearance; }
  /// The block's half side: its corners stay inside the nearest bob's edge.
  double block_half_side() const;
  /// The solid the support stands for, in world units: all above the
  /// ceiling line across its width (the hatching marks a body, not a band),
  /// or the block.
  WorldBox region() const;
  void draw(render::Canvas&, const render::WorldView&, const render::Color& ink) const;

 private:
  Point pivot_;
  double highest_ = -INFINITY;  ///< the highest bob's top
  double nearest_ = INFINITY;   ///< the nearest bob edge's distance from the pivot
};

}  // namespace vibra::scenes
