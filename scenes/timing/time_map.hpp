// TimeMap: video time to simulated time, piecewise linear, for pacing (slow motion and pauses).
#pragma once
#include <vector>

#include "scenes/timing/pacing.hpp"

namespace vibra::scenes {

/// From one moment of the video on, simulated time runs at `rate` per
/// second of video from `simulated` (rate 0: a pause).
struct TimePiece {
  double video = 0, simulated = 0, rate = 0;
};

/// Video time -> simulated time for a run of [0, T] shown at a steady `rate`
/// (simulated time per second of video) except where the pacing slows it or
/// holds it. Piecewise linear and non-decreasing: pauses are flat pieces.
/// The lecture page evaluates the same pieces the same way (page.js).
class TimeMap {
 public:
  /// Throws UsageError when the pacing reaches outside [0, T].
  TimeMap(double T, double rate, const Pacing&);

  /// Simulated time at `video` seconds, within [0, T].
  double simulated(double video) const;
  /// Seconds of video until the run reaches T (its last moment, pauses at T included).
  double duration() const { return duration_; }
  /// The first video time that shows simulated time `t` (a pause's start where one holds `t`).
  double first_video_time(double t) const;
  const std::vector<TimePiece>& pieces() const { return pieces_; }
  /// The run's end time T: where the last piece stops.
  double end() const { return T_; }

 private:
  std::vector<TimePiece> pieces_;
  double T_, duration_;
};

}  // namespace vibra::scenes
