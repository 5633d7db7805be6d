// Pacing: slow motion and pauses over ranges of simulated time (scene key pacing).
#pragma once
#include <string>
#include <vector>

namespace vibra::scenes {

/// Simulated times [from, to] play `factor` times slower than the rest of
/// the video (factor 4: a quarter of the speed; 0.5: twice as fast).
struct SlowMotion {
  double from = 0, to = 0, factor = 1;
};

/// The video holds simulated time `at` for `seconds`.
struct Pause {
  double at = 0, seconds = 0;
};

/// How a render's video time deviates from the steady speed: slow-motion
/// ranges (never overlapping) and pauses (at distinct times), each kept in
/// time order. --slow T0-T1:FACTOR and --pause T:SECONDS, or the scene keys
/// slow and pause.
struct Pacing {
  std::vector<SlowMotion> slow;
  std::vector<Pause> pauses;

  bool empty() const { return slow.empty() && pauses.empty(); }
  /// Adds "T0-T1:FACTOR" (e.g. "2-4:4"). Throws UsageError, one line naming
  /// the fix, for a text that is not that form, T1 <= T0, a factor <= 0 or
  /// beyond 1000, or a range that overlaps one already given.
  void add_slow(const std::string& text);
  /// Adds "T:SECONDS" (e.g. "3:1"). Throws UsageError for another form, a
  /// negative time, seconds <= 0 or beyond 3600, or a second pause at T.
  void add_pause(const std::string& text);
  /// Throws UsageError unless every range and pause lies inside [0, T].
  void check_inside(double T) const;
  /// Extra seconds of video the pacing adds at a steady `rate` (simulated
  /// time per second of video).
  double added_seconds(double rate) const;
  /// The steady rate (simulated time per second of video) that makes a run
  /// of [0, T] last `seconds` of video with this pacing; throws UsageError
  /// when the pauses alone take that long.
  double rate_for_length(double T, double seconds) const;
  /// "slow 2-4:4, pause 3:1": for page facts, file metadata and fingerprints.
  std::string describe() const;
};

}  // namespace vibra::scenes
