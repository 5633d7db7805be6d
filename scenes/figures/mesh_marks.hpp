// vibra plot --annotate mesh (Fig 1.12): where a scheme's unknowns live on the time mesh.
#pragma once
#include <span>
#include <vector>

#include "core/trajectory.hpp"
#include "render/plot/figure.hpp"

namespace vibra::scenes {

/// `vibra plot --annotate mesh` (Fig 1.12): where a scheme's unknowns live on
/// the time mesh. Every time panel gets a dot at each step t_n. With the
/// staggered scheme the velocity's dots sit at the half steps instead:
/// v^{n+1/2} = (u^{n+1} - u^n)/dt is the value the scheme computes (its v
/// column is the mean of the two half steps around t_n).
class MeshMarks {
 public:
  /// Throws UsageError when the run has more steps than the picture can show
  /// apart (one per 8 pixels of `width`).
  MeshMarks(const TrajectoryInfo&, int width);

  /// Adds the dots of the time panel `panel`, which shows `column` scaled by `factor`.
  void mark_panel(render::Figure&, int panel, int column, double factor, render::Color);
  /// A row at a step (not between steps), in time order.
  void observe_step(std::span<const double> row);
  /// The mesh points to tick on the time axis (every t_n of a fixed step when
  /// they are few enough to label; none otherwise).
  std::vector<double> ticks() const;

  /// Where the dots of a panel are: (t, value) pairs, for tests.
  struct Dots {
    render::Series* series;
    int column;
    double factor;
    bool half_steps;
    std::vector<std::pair<double, double>> points;
  };
  const std::vector<Dots>& dots() const { return dots_; }

 private:
  const TrajectoryInfo& info_;
  std::vector<Dots> dots_;
  std::vector<double> previous_;  ///< the row of the step before
  int width_;
  long long steps_seen_ = 0;
};

}  // namespace vibra::scenes
