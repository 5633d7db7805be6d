// SolutionStream: a scheme's samples one at a time in constant memory, stopping at a non-finite value.
#pragma once
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <utility>

#include "core/error.hpp"
#include "core/scheme.hpp"
#include "core/stop_flag.hpp"

namespace vibra {

/// Throws the SolutionError for a non-finite value at step `index`, time `t`.
/// Out of line and cold, so the per-step check stays a pair of compares.
[[noreturn, gnu::cold, gnu::noinline]] void report_non_finite(long long index, double t);

/// The solution as a stream of samples t_0, t_1, ..., t_steps, one at a time,
/// in constant memory: observers (CSV rows, frames, ASCII lines, analysis)
/// consume it as it is computed. A non-finite value stops the stream with a
/// SolutionError naming the step and time. An adaptive stepper's stream
/// ends when its time reaches `end` instead, after however many steps.
/// Every 65536 steps it looks at the stop flag, so every loop over a
/// solution (pre-passes, analyses, convergence studies) ends within a
/// moment of Ctrl-C with Interrupted.
template <int D>
class SolutionStream {
 public:
  static constexpr long long unbounded = std::numeric_limits<long long>::max();

  SolutionStream(AnyStepper<D> stepper, long long steps, double end = std::numeric_limits<double>::infinity())
      : stepper_(std::move(stepper)), steps_(steps), end_(end) {
    current_ = std::visit([](const auto& s) { return s.current(); }, stepper_);
    check(current_);
  }

  const Sample<D>& current() const { return current_; }
  long long index() const { return index_; }
  long long steps() const { return steps_; }
  bool done() const { return index_ >= steps_ || current_.t >= end_; }

  /// The state at t inside the last step from the stepper's own continuous
  /// extension (dopri5's dense output), or empty when it has none.
  std::optional<Sample<D>> dense_at(double t) const {
    return std::visit(
        [t](const auto& s) -> std::optional<Sample<D>> {
          if constexpr (requires { s.dense_at(t); }) return s.dense_at(t);
          else return std::nullopt;
        },
        stepper_);
  }

  /// Moves to the next sample; false (and no change) at the end.
  bool advance() {
    if (done()) return false;
    current_ = std::visit([](auto& s) { s.step(); return s.current(); }, stepper_);
    ++index_;
    check(current_);
    poll_stop(index_, steps_);
    return true;
  }

  /// Calls `observer(sample)` for the current and every following sample
  /// until the end or until the observer returns false. The scheme is chosen
  /// once, outside the loop, so the loop is as tight as a hand-written one.
  template <class Observer>
  void for_each(Observer&& observer) {
    std::visit(
        [&](auto& s) {
          if (!observer(current_)) return;
          while (index_ < steps_ && current_.t < end_) {
            s.step();
            current_ = s.current();
            ++index_;
            check(current_);
            poll_stop(index_, steps_);
            if (!observer(current_)) return;
          }
        },
        stepper_);
  }

 private:
  [[gnu::always_inline]] void check(const Sample<D>& s) const {
    bool finite = true;
    // Bitwise on purpose: no branch per component in the hot loop.
    for (int i = 0; i < D; ++i) finite &= static_cast<int>(std::isfinite(s.u[i])) & static_cast<int>(std::isfinite(s.v[i]));
    if (finite) [[likely]]
      return;
    report_non_finite(index_, s.t);
  }

  AnyStepper<D> stepper_;
  long long steps_;
  double end_;
  long long index_ = 0;
  Sample<D> current_;
};

}  // namespace vibra
