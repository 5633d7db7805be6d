// A value at the two samples around a frame of a straight run, so a quantity of the rows is drawn on its chord.
#pragma once
#include <cmath>
#include <optional>

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
/// Fed the quantity at each sample of its run as the render pass observes
/// it, and at the run's next sample before a frame (Scene::look_ahead), it
/// gives the value on that straight line.
class SampleBracket {
 public:
  /// The value at a sample observed (NaN where the run has no sample: kept out).
  void observe(double t, double value) {
    if (std::isfinite(value)) t0_ = t, v0_ = value;
  }
  /// The value at the run's next sample, or none (NaN).
  void look_ahead(double t, double value) { t1_ = std::isfinite(value) ? t : NAN, v1_ = value; }

  /// v_n + s (v_n+1 - v_n), s = (t - t_n) / (t_n+1 - t_n), when t lies
  /// strictly between the two samples; none otherwise.
  std::optional<double> on_chord(double t) const {
    if (!(t0_ < t && t < t1_)) return std::nullopt;
    const double s = (t - t0_) / (t1_ - t0_);
    return v0_ + s * (v1_ - v0_);
  }

 private:
  double t0_ = NAN, v0_ = NAN, t1_ = NAN, v1_ = NAN;
};

}  // namespace vibra::scenes
