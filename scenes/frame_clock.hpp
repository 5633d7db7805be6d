#pragma once
#include <cmath>

#include "core/error.hpp"

namespace vibra::scenes {

/// When each video frame happens in simulated time. Frame k shows
/// t_k = k * speed / fps for k = 0, 1, ... while t_k <= T; with one frame per
/// solver step, t_k = k * dt.
class FrameClock {
 public:
  /// More frames than any sensible video (about 39 days at 30 fps).
  static constexpr double kMaxFrames = 1e8;

  /// `speed`: simulated time units per second of video. Throws UsageError
  /// when the count is not finite or exceeds kMaxFrames.
  static FrameClock by_speed(double T, double fps, double speed) {
    return FrameClock(speed / fps, std::floor(T / (speed / fps) * (1 + 1e-12)) + 1);
  }
  static FrameClock per_step(double dt, long long steps) { return FrameClock(dt, double(steps) + 1); }

  long long frames() const { return frames_; }
  double time(long long k) const { return k * interval_; }
  double interval() const { return interval_; }

 private:
  FrameClock(double interval, double frames) : interval_(interval), frames_(checked(frames)) {}
  // Checked as a double: converting a huge or non-finite count to an integer is undefined.
  static long long checked(double frames) {
    if (!(frames >= 1 && frames <= kMaxFrames))
      throw UsageError("that is more than 1e8 frames: lower fps, raise speed or shorten T");
    return static_cast<long long>(frames);
  }
  double interval_;
  long long frames_;
};

}  // namespace vibra::scenes
