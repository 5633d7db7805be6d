// TimeMap: video time to simulated time, piecewise linear, for pacing (slow motion and pauses).
#include "scenes/timing/time_map.hpp"

#include <algorithm>

namespace vibra::scenes {

TimeMap::TimeMap(double T, double rate, const Pacing& pacing) : T_(T) {
  pacing.check_inside(T);
  // Walk the run's time from 0 to T; each change of pace starts a piece.
  struct Change {
    double at;
    int kind;  // 0: a pause, 1: slow motion ends, 2: slow motion starts (a pause at a range's start holds first)
    double value;
  };
  std::vector<Change> changes;
  for (const SlowMotion& s : pacing.slow) changes.push_back({s.from, 2, s.factor}), changes.push_back({s.to, 1, 1});
  for (const Pause& p : pacing.pauses) changes.push_back({p.at, 0, p.seconds});
  std::stable_sort(changes.begin(), changes.end(), [](const Change& a, const Change& b) {
    return a.at != b.at ? a.at < b.at : a.kind < b.kind;
  });
  double video = 0, t = 0, factor = 1;
  auto advance_to = [&](double to) {
    if (to <= t) return;
    if (pieces_.empty() || pieces_.back().rate != rate / factor) pieces_.push_back({video, t, rate / factor});
    video += (to - t) * factor / rate;
    t = to;
  };
  for (const Change& c : changes) {
    advance_to(c.at);
    if (c.kind == 0) {
      pieces_.push_back({video, t, 0});
      video += c.value;
    } else {
      factor = c.kind == 2 ? c.value : 1;
    }
  }
  advance_to(T);
  if (pieces_.empty()) pieces_.push_back({0, 0, rate});
  duration_ = video;
}

double TimeMap::simulated(double video) const {
  auto after = std::upper_bound(pieces_.begin(), pieces_.end(), video,
                                [](double v, const TimePiece& p) { return v < p.video; });
  if (after == pieces_.begin()) return 0;
  const TimePiece& p = *(after - 1);
  const double end = after == pieces_.end() ? T_ : after->simulated;
  return std::min(end, p.simulated + (video - p.video) * p.rate);
}

double TimeMap::first_video_time(double t) const {
  for (std::size_t i = 0; i < pieces_.size(); ++i) {
    const TimePiece& p = pieces_[i];
    const double end = i + 1 < pieces_.size() ? pieces_[i + 1].simulated : T_;
    if (t <= end && (p.rate > 0 || t == p.simulated)) return p.video + (p.rate > 0 ? (t - p.simulated) / p.rate : 0);
  }
  return duration_;
}

}  // namespace vibra::scenes
