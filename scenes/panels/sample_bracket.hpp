// The two solver samples around a frame of a fixed-step run, so a quantity of the rows is drawn on its chord.
#pragma once
#include <optional>
#include <span>
#include <vector>

namespace vibra::scenes {

/// A fixed-step run is its samples joined by straight lines: between t_n and
/// t_n+1 its state is the chord (1 - s) y_n + s y_n+1. A quantity that is
/// not linear in the state (an energy, the orbit's radius, an error against
/// a curve) then has two values at such a t: of the state on the chord, and
/// on the straight line between its own values at the samples. A panel draws
/// the second, as its curve joins the samples' values: the first leaves the
/// curve (a circular orbit's chord lies inside the circle, so r dips by
/// 1 - cos(pi/N) at N steps a period, where PEFRL's r drifts by 2e-8).
///
/// Fed the last sample observed at or before a frame (observe) and the
/// solver's next sample after it (look_ahead, empty when the run curves
/// between its samples or t is a sample), it gives a quantity's value on
/// that straight line.
class SampleBracket {
 public:
  void observe(std::span<const double> sample) { before_.assign(sample.begin(), sample.end()); }
  void look_ahead(std::span<const double> next_sample) { after_.assign(next_sample.begin(), next_sample.end()); }

  /// s = (t - t_n) / (t_n+1 - t_n) when t lies strictly between the two samples; none otherwise.
  std::optional<double> fraction(double t) const {
    if (before_.empty() || after_.empty() || !(before_[0] < t && t < after_[0])) return std::nullopt;
    return (t - before_[0]) / (after_[0] - before_[0]);
  }
  std::span<const double> before() const { return before_; }
  std::span<const double> after() const { return after_; }

  /// value(y_n) + s (value(y_n+1) - value(y_n)) when t lies strictly between
  /// the two samples; none otherwise.
  template <class Value>
  std::optional<double> on_chord(double t, const Value& value) const {
    const std::optional<double> s = fraction(t);
    if (!s) return std::nullopt;
    const double from = value(before()), to = value(after());
    return from + *s * (to - from);
  }

 private:
  std::vector<double> before_, after_;
};

}  // namespace vibra::scenes
