// One scale per run for a diagram's force arrows, with the longest arrow its part has room for.
#pragma once
#include <algorithm>
#include <cmath>

#include "scenes/diagrams/diagram.hpp"

namespace vibra::scenes {

/// One scale for every force arrow of a diagram, chosen per run from the
/// forces of its pre-pass (docs/drawing.md): the largest force is drawn
/// `longest` world units long (the room the view, set by the bodies, leaves
/// around them), so arrows compare across forces and across the run. When
/// that would draw the reference force (mg, the forcing's amplitude) shorter
/// than kLeastShare of `longest`, the reference gets that share instead and
/// forces longer than `longest` are drawn clipped to it with a break mark
/// (draw_broken_force): at resonance the spring force is twenty times the
/// forcing, and one plain scale would draw the forcing as a dot.
class ForceScale {
 public:
  static constexpr double kLeastShare = 0.4;

  void see(double force) {
    if (std::isfinite(force)) largest_ = std::max(largest_, std::abs(force));
  }
  void set_longest(double world_length) { longest_ = world_length; }
  /// The force that must read at any scale; 0: none.
  void set_reference(double force) { reference_ = std::abs(force); }
  /// World units per unit of force.
  double per_force() const {
    if (!(largest_ > 0)) return 0;
    const double fit = longest_ / largest_;
    return reference_ > 0 ? std::max(fit, kLeastShare * longest_ / reference_) : fit;
  }
  double length(double force) const { return force * per_force(); }
  double largest() const { return largest_; }
  double longest() const { return longest_; }
  /// Whether an arrow of this many world units is drawn clipped.
  bool clips(double world_length) const { return clips(world_length, longest_); }
  static bool clips(double world_length, double room) { return std::abs(world_length) > room * (1 + 1e-9); }
  /// The arrow as drawn: at most `room` (by default `longest`) long.
  Arrow clipped(const Arrow& a) const { return clipped(a, longest_); }
  static Arrow clipped(const Arrow& a, double room) {
    const Point along = a.to - a.from;
    const double n = along.norm();
    return clips(n, room) ? Arrow{a.from, a.from + room / n * along} : a;
  }

 private:
  double largest_ = 0, reference_ = 0;
  double longest_ = 1;
};

}  // namespace vibra::scenes
