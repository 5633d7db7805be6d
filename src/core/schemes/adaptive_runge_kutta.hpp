#pragma once
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>

#include "core/schemes/embedded_pairs.hpp"
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
/// at most 1; the next step is scaled by 0.9 err^(-1/(order+1)), within
/// [0.2, 5] (no growth right after a rejection). The first step follows
/// Hairer, Norsett and Wanner's starting rule. Steps never exceed 1000 dt,
/// so a solution at rest still reports now and then.
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

 private:
  Y rhs(const Y& y, double t) const { return first_order_rhs<D>(*sys_, y, t); }

  double scaled_rms(const Y& x, const Y& scale) const { return std::sqrt((x.array() / scale.array()).square().mean()); }

  double starting_step() const {
    const Y scale = control_.atol + control_.rtol * y_.array().abs();
    const double d0 = scaled_rms(y_, scale), d1 = scaled_rms(f_, scale);
    double h0 = d0 < 1e-5 || d1 < 1e-5 ? 1e-6 : 0.01 * d0 / d1;
    h0 = std::min({h0, max_step_, control_.end - t_});
    const double d2 = scaled_rms(rhs(y_ + h0 * f_, t_ + h0) - f_, scale) / h0;
    const double d = std::max(d1, d2);
    const double h1 = d <= 1e-15 ? std::max(1e-6, h0 * 1e-3) : std::pow(0.01 / d, 1.0 / (Pair::order + 1));
    return std::min({100 * h0, h1, max_step_});
  }

  /// One accepted step, shortened where it would pass `limit`.
  void accept_one(double limit) {
    constexpr int S = Pair::stages;
    std::array<Y, S> k;
    for (bool rejected_before = false;;) {
      // Within 1% of the limit the step stretches to it (a sliver of a step
      // would follow otherwise); its error is checked like any other.
      const bool clipped = 1.01 * h_ >= limit - t_;
      const double h = clipped ? limit - t_ : h_;
      k[0] = f_;
      for (int i = 1; i < S; ++i) {
        Y y = y_;
        for (int j = 0; j < i; ++j)
          if (Pair::a[i][j] != 0) y += h * Pair::a[i][j] * k[j];
        k[i] = rhs(y, t_ + Pair::c[i] * h);
      }
      Y y_new = y_, error = Y::Zero();
      for (int i = 0; i < S; ++i) {
        if (Pair::b[i] != 0) y_new += h * Pair::b[i] * k[i];
        if (Pair::e[i] != 0) error += h * Pair::e[i] * k[i];
      }
      const Y scale = control_.atol + control_.rtol * y_.array().abs().max(y_new.array().abs());
      const double err = scaled_rms(error, scale);
      double factor = 0.9 * std::pow(err, -1.0 / (Pair::order + 1));
      if (!(factor >= 0.2)) factor = 0.2;  // also for a NaN error: a non-finite stage
      factor = std::min(factor, rejected_before ? 1.0 : 5.0);
      if (err <= 1 && y_new.allFinite()) {
        const double t_new = clipped ? limit : t_ + h;
        const Y f_new = Pair::first_same_as_last ? k[S - 1] : rhs(y_new, t_new);
        if constexpr (Pair::dense) {
          Y dk = Y::Zero();
          for (int i = 0; i < S; ++i) dk += Pair::d[i] * k[i];
          const Y difference = y_new - y_, slope_start = h * f_ - difference;
          dense_ = {y_, difference, slope_start, difference - h * f_new - slope_start, h * dk};
        }
        t_previous_ = t_;
        t_ = t_new, y_ = y_new, f_ = f_new;
        // A step cut short at the limit says nothing against the longer one.
        h_ = std::min(max_step_, clipped ? std::max(h_, h * factor) : h * factor);
        ++accepted_;
        return;
      }
      ++rejected_;
      rejected_before = true;
      h_ = h * factor;
      if (!(h_ > 1e-14 * std::max(1.0, std::abs(t_))))
        throw SolutionError("the step size of the adaptive scheme fell below 1e-14 at t = " + std::to_string(t_) +
                                ": the solution is not smooth there or rtol/atol are too tight; loosen them",
                            accepted_, t_);
    }
  }

  const SecondOrderSystem<D>* sys_;
  double dt_;
  StepControl control_;
  double max_step_;
  double t_ = 0, t_previous_ = 0, h_ = 0;
  long long mesh_index_ = 0, accepted_ = 0, rejected_ = 0;
  Y y_, f_;
  std::array<Y, 5> dense_{};
};

template <int D>
using RungeKuttaFehlberg = AdaptiveRungeKutta<D, Fehlberg45>;
template <int D>
using DormandPrince = AdaptiveRungeKutta<D, DormandPrince54>;

}  // namespace vibra
