// The --panels friction figure of the sliding box (Exercise 1.23a): spring force against u and the friction band.
#pragma once
#include <span>
#include <string>
#include <vector>

#include "core/trajectory.hpp"
#include "render/plot/figure.hpp"

namespace vibra::scenes {

/// `--panels friction` (the sliding box, Exercise 1.23a): the spring force
/// s(u) = tanh(alpha u)/alpha against u, the friction band |s| <= mu where the
/// box can come to rest, and each run's turning points on its s(u). From
/// rest, a linear spring's turning points step inwards by 2 mu per half swing
/// until one lands inside the band: the last is where the box stays.
class FrictionPanel {
 public:
  /// One member per run (a comparison's members in their colours); `labels`
  /// name them in the legend (empty for a single run).
  struct Member {
    const TrajectoryInfo* info;
    render::Color color;
    std::string label;
  };
  /// Adds the panel below the figure's others. Throws UsageError when a
  /// member's model has no spring against friction.
  FrictionPanel(render::Figure&, std::vector<Member> members);

  /// A row (t, u, v, ...) of member m, in time order.
  void observe(size_t member, std::span<const double> row);
  /// Samples each s(u) over the range of u seen, symmetric about 0, and draws the band.
  void finish();

  /// Member m's turning points so far, in order: where v came to 0 or changed sign.
  const std::vector<double>& turning_points(size_t member) const { return runs_[member].turns; }

 private:
  struct Run {
    Member member;
    render::Series* curve;
    render::Series* turns_drawn;
    std::vector<double> turns;
    double previous_u = 0, previous_v = 0;
    bool started = false;
  };
  render::Figure& figure_;
  int panel_;
  std::vector<Run> runs_;
  double reach_ = 0;  ///< largest |u| seen over all members
};

}  // namespace vibra::scenes
