// The adaptive Runge-Kutta stepper over an embedded pair (rkf45, dopri5), with step size control.
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <string>

#include "core/schemes/embedded_pairs.hpp"
#include "core/schemes/step_controller.hpp"
#include "core/schemes/step_refusal.hpp"
#include "core/stop_flag.hpp"
#include "core/schemes/newton.hpp"
#include "core/second_order_system.hpp"

namespace vibra {

/// What an adaptive scheme is asked for.
struct StepControl {
  double rtol = 1e-6;  ///< relative tolerance of each step's local error
  double atol = 1e-9;  ///< absolute tolerance, for components passing through 0
  /// The run's end: no step goes past it (infinite for an endless run).
  double end = std::numeric_limits<double>::infinity();
  /// False: each step() is one accepted step of the scheme's own size, so
  /// the samples fall at uneven times. True: each step() ends on the next
  /// mesh point k dt, with as many accepted steps inside as the tolerance
  /// needs (for models that cut steps at events).
  bool on_mesh = false;
};

/// An embedded Runge-Kutta pair (core/schemes/embedded_pairs.hpp) with step
/// size control for y = (u, v), y' = (v, a(u, v, t)). A step is accepted
/// when the error estimate, measured per component against
/// atol + rtol max(|y^n|, |y^{n+1}|) and averaged as a root mean square, is
/// at most 1; the next step follows core/schemes/step_controller.hpp. The
/// first step follows Hairer, Norsett and Wanner's starting rule. Steps
/// never exceed 1000 dt, so a solution at rest still reports now and then.
/// A run that cannot advance in doubles ends with a UsageError
/// (core/schemes/step_refusal.hpp), never with steps that leave t where it is.
template <int D, class Pair>
class AdaptiveRungeKutta {
  using Y = Eigen::Matrix<double, 2 * D, 1>;

 public:
  AdaptiveRungeKutta(const SecondOrderSystem<D>& system, const Vec<D>& u0, const Vec<D>& v0, double dt,
                     const StepControl& control)
      : sys_(&system), dt_(dt), control_(control), max_step_(1000 * dt) {
    y_ << u0, v0;
    f_ = rhs(y_, 0);
    h_ = starting_step();
  }

  Sample<D> current() const { return {t_, y_.template head<D>(), y_.template tail<D>()}; }

  void step() {
    if (control_.on_mesh) {
      const double target = ++mesh_index_ * dt_;
      while (t_ < target) accept_one(target);
    } else {
      accept_one(control_.end);
    }
  }

  /// Accepted and rejected steps so far.
  long long accepted() const { return accepted_; }
  long long rejected() const { return rejected_; }
  /// The size the next step will try (before any cut at the run's end).
  double next_step() const { return h_; }

  /// The state at t inside the last step from the scheme's continuous
  /// extension, where the pair has one (empty otherwise, or before the
  /// first step).
  std::optional<Sample<D>> dense_at(double t) const {
    if constexpr (!Pair::dense) {
      return std::nullopt;
    } else {
      if (accepted_ == 0 || !(t_ > t_previous_)) return std::nullopt;
      const double s = std::clamp((t - t_previous_) / (t_ - t_previous_), 0.0, 1.0), r = 1 - s;
      const Y y = dense_[0] + s * (dense_[1] + r * (dense_[2] + s * (dense_[3] + r * dense_[4])));
      return Sample<D>{t, y.template head<D>(), y.template tail<D>()};
    }
  }

  /// The root mean square of x_i / scale_i without overflow in the squares;
  /// a component with x_i = 0 adds 0 even at scale 0 (atol = 0 on a
  /// component at rest). NaN if any ratio is NaN, inf if any is infinite.
  static double scaled_rms(const Y& x, const Y& scale) {
    Y ratio;
    for (int i = 0; i < 2 * D; ++i) ratio[i] = x[i] == 0 ? 0 : x[i] / scale[i];
    // The plain sum of squares wherever it neither overflows nor underflows.
    const double mean_square = ratio.array().square().mean();
    if (mean_square >= std::numeric_limits<double>::min() && mean_square < HUGE_VAL) return std::sqrt(mean_square);
    double largest = 0;
    for (int i = 0; i < 2 * D; ++i)
      if (!(std::abs(ratio[i]) <= largest)) largest = std::abs(ratio[i]);  // NaN sticks
    if (!(largest > 0 && largest < HUGE_VAL)) return largest;
    return largest * std::sqrt((ratio / largest).array().square().mean());
  }

 private:
  using Stages = std::array<Y, Pair::stages>;

  Y rhs(const Y& y, double t) const { return first_order_rhs<D>(*sys_, y, t); }

  double starting_step() const {
    const Y scale = control_.atol + control_.rtol * y_.array().abs();
    const double d0 = scaled_rms(y_, scale), d1 = scaled_rms(f_, scale);
    // A norm that is not finite (a component at 0 with atol = 0) says as
    // little as one that is tiny: the rule's fallbacks then.
    double h0 = d0 < 1e-5 || !(d1 >= 1e-5 && d1 < HUGE_VAL) ? 1e-6 : 0.01 * d0 / d1;
    h0 = std::max(std::min({h0, max_step_, control_.end - t_}), shortest_step(t_));
    const double d2 = scaled_rms(rhs(y_ + h0 * f_, t_ + h0) - f_, scale) / h0;
    const double d = std::max(d1, d2);
    const double h1 =
        !(d > 1e-15 && d < HUGE_VAL) ? std::max(1e-6, h0 * 1e-3) : std::pow(0.01 / d, 1.0 / (Pair::order + 1));
    return std::max(std::min({100 * h0, h1, max_step_}), shortest_step(t_));
  }

  /// The stages of a step of size h from (t_, y_), the new state and the
  /// error estimate's norm.
  struct Attempt {
    Stages k;
    Y y_new;
    double error_norm;
  };
  Attempt attempt(double h) const {
    Attempt a;
    a.k[0] = f_;
    for (int i = 1; i < Pair::stages; ++i) {
      Y y = y_;
      for (int j = 0; j < i; ++j)
        if (Pair::a[i][j] != 0) y += h * Pair::a[i][j] * a.k[j];
      a.k[i] = rhs(y, t_ + Pair::c[i] * h);
    }
    Y error = Y::Zero();
    a.y_new = y_;
    for (int i = 0; i < Pair::stages; ++i) {
      if (Pair::b[i] != 0) a.y_new += h * Pair::b[i] * a.k[i];
      if (Pair::e[i] != 0) error += h * Pair::e[i] * a.k[i];
    }
    const Y scale = control_.atol + control_.rtol * y_.array().abs().max(a.y_new.array().abs());
    a.error_norm = scaled_rms(error, scale);
    return a;
  }

  /// One accepted step, shortened where it would pass `limit`. Each try
  /// looks at the stop flag now and then: one call may try many.
  void accept_one(double limit) {
    bool non_finite = false;
    for (int rejections = 0;; ++rejections) {
      poll_stop(++tries_);
      // Within 1% of the limit the step stretches to it (a sliver of a step
      // would follow otherwise); its error is checked like any other.
      const bool clipped = 1.01 * h_ >= limit - t_;
      const double h = clipped ? limit - t_ : h_;
      if (!clipped && !(h >= shortest_step(t_)))
        refuse(non_finite ? StepFailure::non_finite_error : StepFailure::step_underflow, h);
      const Attempt a = attempt(h);
      const StepVerdict verdict = judge_step<Pair::order>(a.error_norm, rejections > 0);
      if (verdict.accepted && a.y_new.allFinite()) return take(a, h, clipped, clipped ? limit : t_ + h, verdict.factor);
      ++rejected_;
      non_finite = !std::isfinite(a.error_norm);
      if (rejections + 1 >= StepControllerLimits::rejections_in_a_row)
        refuse(non_finite ? StepFailure::non_finite_error : StepFailure::rejected_in_a_row, h);
      h_ = h * verdict.factor;
    }
  }

  /// Moves to the accepted step's end t_new; the next step is `factor` times
  /// this one (a step cut short at the limit says nothing against the
  /// longer one).
  void take(const Attempt& a, double h, bool clipped, double t_new, double factor) {
    const Y f_new = Pair::first_same_as_last ? a.k[Pair::stages - 1] : rhs(a.y_new, t_new);
    if constexpr (Pair::dense) {
      Y dk = Y::Zero();
      for (int i = 0; i < Pair::stages; ++i) dk += Pair::d[i] * a.k[i];
      const Y difference = a.y_new - y_, slope_start = h * f_ - difference;
      dense_ = {y_, difference, slope_start, difference - h * f_new - slope_start, h * dk};
    }
    t_previous_ = t_;
    t_ = t_new, y_ = a.y_new, f_ = f_new;
    h_ = std::min(max_step_, clipped ? std::max(h_, h * factor) : h * factor);
    ++accepted_;
  }

  [[noreturn]] void refuse(StepFailure failure, double h) const {
    refuse_adaptive_step(Pair::name, failure, t_, h);
  }

  const SecondOrderSystem<D>* sys_;
  double dt_;
  StepControl control_;
  double max_step_;
  double t_ = 0, t_previous_ = 0, h_ = 0;
  long long mesh_index_ = 0, accepted_ = 0, rejected_ = 0, tries_ = 0;
  Y y_, f_;
  std::array<Y, 5> dense_{};
};

template <int D>
using RungeKuttaFehlberg = AdaptiveRungeKutta<D, Fehlberg45>;
template <int D>
using DormandPrince = AdaptiveRungeKutta<D, DormandPrince54>;

}  // namespace vibra
