#pragma once
#include <cmath>

namespace vibra::scenes {

/// When each video frame happens in simulated time. Frame k shows
/// t_k = k * speed / fps for k = 0, 1, ... while t_k <= T; with one frame per
/// solver step, t_k = k * dt.
class FrameClock {
 public:
  /// `speed`: simulated time units per second of video.
  static FrameClock by_speed(double T, double fps, double speed) {
    return FrameClock(speed / fps, std::floor(T / (speed / fps) * (1 + 1e-12)) + 1);
  }
  static FrameClock per_step(double dt, long long steps) { return FrameClock(dt, steps + 1); }

  long long frames() const { return frames_; }
  double time(long long k) const { return k * interval_; }
  double interval() const { return interval_; }

 private:
  FrameClock(double interval, double frames) : interval_(interval), frames_(static_cast<long long>(frames)) {}
  double interval_;
  long long frames_;
};

}  // namespace vibra::scenes
