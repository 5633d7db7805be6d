// Feeds a scene a trajectory's history in time order: every solver step, and the rows between them where needed.
#pragma once
#include <span>
#include <vector>

#include "core/trajectory.hpp"
#include "scenes/scene.hpp"

namespace vibra::scenes {

/// Feeds a scene a trajectory's history in time order: every solver step
/// and, for a run whose rows between steps leave the straight line between
/// them (an adaptive scheme's dense output, an impact inside a step:
/// Trajectory::bends_between_samples) where steps are
/// coarser than the scene's curves resolve (Scene::sample_interval), rows
/// interpolated between them on one grid of times fixed for the whole run.
/// A fixed-step run gets its mesh rows alone: drawn joined by straight lines,
/// they are what the scheme computed, and sums and panels of energy, error
/// and period see mesh values only. Curves, markers and the diagram then show
/// one interpolation of the same samples, and what a frame shows does not
/// depend on how many steps fall in it.
///
/// The pre-pass records every row of the run; the render pass observes rows
/// up to each frame's time and no further, so a trail or a moving curve ends
/// where the frame's marker is.
class HistoryFeed {
 public:
  /// `interval`: the grid's spacing (0: steps only).
  HistoryFeed(Trajectory& trajectory, Scene& scene, double interval);

  /// The pre-pass: records the whole run (calling `each_step(row)` for every
  /// solver step as well, and checking the stop flag).
  template <class EachStep>
  void record_all(EachStep&& each_step) {
    std::vector<double> row(trajectory_.width());
    do {
      trajectory_.row(row);
      if (trajectory_.index() > 0) feed_between(false, trajectory_.t());
      sample_.assign(row.begin(), row.end());  // each_step gets every run, the scene each at its own samples
      trajectory_.hide_runs_between_their_samples(sample_);
      scene_.record(sample_);
      each_step(row);
      poll_stop();
      previous_t_ = trajectory_.t();
    } while (trajectory_.advance());
  }

  /// The render pass: observes everything up to t, then returns the row at t
  /// (and gives the scene each run's next sample, Scene::look_ahead).
  std::span<const double> row_at(double t);

 private:
  /// Interpolated rows strictly inside the current step interval, up to `limit`.
  void feed_between(bool observe, double limit);
  void poll_stop();

  Trajectory& trajectory_;
  Scene& scene_;
  double interval_;
  double previous_t_;            ///< the step before the current one
  long long next_grid_ = 1;      ///< the next grid time to feed is next_grid_ * interval_
  bool step_observed_ = false;   ///< the current step's row was observed
  long long polls_ = 0;
  std::vector<double> row_, between_, sample_;
  std::vector<std::vector<double>> ahead_;
};

}  // namespace vibra::scenes
