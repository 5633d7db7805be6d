#pragma once
#include <algorithm>
#include <cmath>

namespace vibra::scenes {

/// One scale for every force arrow of a diagram: the largest force seen in
/// the pre-pass is drawn `longest` world units long, so arrows compare
/// across forces and across the run.
class ForceScale {
 public:
  void see(double force) {
    if (std::isfinite(force)) largest_ = std::max(largest_, std::abs(force));
  }
  void set_longest(double world_length) { longest_ = world_length; }
  /// World units per unit of force.
  double per_force() const { return largest_ > 0 ? longest_ / largest_ : 0; }
  double length(double force) const { return force * per_force(); }
  double largest() const { return largest_; }

 private:
  double largest_ = 0;
  double longest_ = 1;
};

}  // namespace vibra::scenes
