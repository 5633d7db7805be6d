// FrameClock: the simulated time of each video frame, steady or paced.
#pragma once
#include <cmath>
#include <optional>

#include "core/error.hpp"
#include "scenes/timing/time_map.hpp"

namespace vibra::scenes {

/// When each video frame happens in simulated time. Frame k shows
/// t_k = k * speed / fps for k = 0, 1, ... while t_k <= T; with one frame per
/// solver step, t_k = k * dt. With pacing (slow motion, pauses), frame k
/// shows the time map's simulated time at k / fps seconds of video.
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
  /// by_speed with slow motion and pauses; without them exactly by_speed.
  static FrameClock paced(double T, double fps, double speed, const Pacing& pacing) {
    if (pacing.empty()) return by_speed(T, fps, speed);
    TimeMap map(T, speed, pacing);
    FrameClock clock(speed / fps, std::floor(map.duration() * fps * (1 + 1e-12)) + 1);
    clock.fps_ = fps;
    clock.map_.emplace(std::move(map));
    return clock;
  }

  long long frames() const { return frames_; }
  double time(long long k) const { return map_ ? map_->simulated(double(k) / fps_) : k * interval_; }
  /// Simulated time per frame at the steady speed (outside slow motion).
  double interval() const { return interval_; }
  /// Whether frame k shows the same time as frame k - 1 (a pause): the same picture.
  bool repeats(long long k) const { return map_ && k > 0 && time(k) == time(k - 1); }
  /// The first frame that shows time t or later; frames() when none does.
  long long first_frame_from(double t) const {
    long long lo = 0, hi = frames_;  // time(hi) >= t holds for the answer, and time(lo - 1) < t
    while (lo < hi) {
      const long long mid = lo + (hi - lo) / 2;
      if (time(mid) >= t) hi = mid;
      else lo = mid + 1;
    }
    return lo;
  }
  /// The frame whose picture frame k shows: the first of a pause's repeats
  /// (the first frame of its time; found by halving, however long the pause).
  long long drawn_frame(long long k) const { return k > 0 && k < frames_ ? first_frame_from(time(k)) : k; }
  /// The pacing's time map; nullopt for a steady clock.
  const std::optional<TimeMap>& time_map() const { return map_; }

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
  double fps_ = 0;
  std::optional<TimeMap> map_;
};

}  // namespace vibra::scenes
