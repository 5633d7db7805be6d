// Feeds a scene a trajectory's history in time order: every solver step, and the rows between them where needed.
#include "scenes/panels/history_feed.hpp"

#include <cmath>

#include "render/output/stop_signal.hpp"

namespace vibra::scenes {

HistoryFeed::HistoryFeed(Trajectory& trajectory, Scene& scene, double interval)
    : trajectory_(trajectory),
      scene_(scene),
      // Rows between samples only where they follow a curve (an adaptive
      // scheme's dense output): a fixed-step run is its mesh values joined by
      // straight lines, which its samples alone draw. At most a few million
      // grid rows over the run, whatever the window asks.
      interval_(trajectory.bends_between_samples() && std::isfinite(interval) && interval > 0
                    ? std::max(interval, trajectory.info().mesh.T / 4e6)
                    : 0),
      previous_t_(trajectory.t()),
      row_(trajectory.width()),
      between_(trajectory.width()) {
  if (!std::isfinite(interval_)) interval_ = 0;
}

void HistoryFeed::poll_stop() {
  if ((++polls_ & 0xfff) == 0) render::throw_if_stop_requested();
}

void HistoryFeed::feed_between(bool observe, double limit) {
  if (interval_ <= 0) return;
  const double end = trajectory_.t();
  // The grid is fed only inside steps longer than it: fine steps need none.
  if (end - previous_t_ <= interval_) {
    next_grid_ = std::max(next_grid_, static_cast<long long>(std::floor(end / interval_)) + 1);
    return;
  }
  if (next_grid_ * interval_ <= previous_t_) next_grid_ = static_cast<long long>(std::floor(previous_t_ / interval_)) + 1;
  for (double g; (g = next_grid_ * interval_) < end && g <= limit; ++next_grid_) {
    if (g <= previous_t_) continue;
    trajectory_.row_at(g, between_);
    trajectory_.hide_runs_between_their_samples(between_);
    if (observe) scene_.observe_between(between_);
    else scene_.record_between(between_);
    poll_stop();
  }
}

std::span<const double> HistoryFeed::row_at(double t) {
  for (;;) {
    feed_between(true, t);
    if (!step_observed_ && trajectory_.t() <= t) {
      trajectory_.row(row_);
      trajectory_.hide_runs_between_their_samples(row_);
      scene_.observe(row_);
      step_observed_ = true;
    }
    if (trajectory_.t() >= t) break;
    const double before = trajectory_.t();
    if (!trajectory_.advance()) break;
    previous_t_ = before;
    step_observed_ = false;
    poll_stop();
  }
  // The next sample of each run that is straight between its samples: the
  // scene's panels draw a quantity of the rows at t on the line between the
  // values at the samples around t, where their curves run.
  trajectory_.straight_samples_ahead(ahead_);
  scene_.look_ahead(ahead_);
  trajectory_.row_at(t, row_);
  return row_;
}

}  // namespace vibra::scenes
