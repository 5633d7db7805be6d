// Trajectories of piecewise-smooth models: events (turning points, impacts) located between steps.
#include "core/event_trajectory.hpp"

#include <cmath>
#include <string>

#include "core/error.hpp"
#include "core/math/hermite.hpp"
#include "core/math/linear_between.hpp"
#include "core/solution_stream.hpp"

namespace vibra {

EventTrajectory::EventTrajectory(EventLaw law, double u0, double v0, EventOutcome start, TrajectoryInfo info,
                                 RowFunction to_row)
    : Trajectory(std::move(info)), law_(std::move(law)), to_row_(std::move(to_row)) {
  rest_ = start.rest;
  direction_ = start.direction;
  current_ = {0, Vec<1>(rest_ ? start.u : u0), Vec<1>(rest_ ? 0.0 : v0)};
  if (!rest_) restart(current_, info_.mesh.dt);
  knots_ = {knot(current_)};
}

EventTrajectory::Knot EventTrajectory::knot(const Sample<1>& s) const {
  return {s, rest_ ? Vec<1>::Zero() : law_.system->acceleration(s.u, s.v, s.t)};
}

void EventTrajectory::restart(const Sample<1>& from, double step) {
  // An adaptive scheme ends each of its calls on the mesh, like the others.
  stepper_.emplace(make_stepper<1>(info_.mesh.scheme, *law_.system, from.u, from.v, step, info_.mesh.control(true)));
  stepper_dt_ = step;
}

Sample<1> EventTrajectory::take_step() {
  return std::visit(
      [](auto& s) {
        s.step();
        return s.current();
      },
      *stepper_);
}

bool EventTrajectory::advance() {
  if (done()) return false;
  const double dt = info_.mesh.dt, t_target = double(index_ + 1) * dt;
  knots_.assign(1, knot(current_));
  ++index_;
  if (rest_) {
    current_.t = t_target;
    knots_.push_back(knot(current_));
    return true;
  }
  Knot at = knots_.back();
  for (int events = 0;; ++events) {
    if (events > 10000)
      throw SolutionError("more than 10000 events in step " + std::to_string(index_) + ": reduce dt", index_, t_target);
    Sample<1> next = take_step();
    next.t = t_target;  // every step taken here ends on the mesh point
    if (!std::isfinite(next.u[0]) || !std::isfinite(next.v[0])) report_non_finite(index_, t_target);
    const Knot after_step = knot(next);
    auto g = [&](double s) {
      const Sample<1> x = hermite_between<1>(at.s, at.acceleration, after_step.s, after_step.acceleration,
                                            at.s.t + s * (t_target - at.s.t));
      return direction_ * law_.event_value(x.u[0], x.v[0]);
    };
    if (g(1) > 0) {
      knots_.push_back(after_step);
      break;
    }
    // The event lies in (at, next]: find a point inside the segment (g > 0),
    // then bisect toward the first zero after it.
    double lo = -1, hi = 1;
    for (int j = 1; j <= 32 && lo < 0; ++j) {
      const double s = j / 32.0;
      if (g(s) > 0) continue;
      hi = s;
      if (j > 1 || g(0) > 0) lo = j > 1 ? (j - 1) / 32.0 : 0;
      for (double r = s / 2; lo < 0 && r > 1e-12; r /= 2)
        if (g(r) > 0) lo = r;
        else hi = r;
      if (lo < 0) lo = hi = 0;  // the segment cannot start: the event is at once
      break;
    }
    for (int i = 0; i < 80 && hi - lo > 1e-16; ++i) {
      const double mid = 0.5 * (lo + hi);
      (g(mid) > 0 ? lo : hi) = mid;
    }
    const double t_event = at.s.t + hi * (t_target - at.s.t);
    const Sample<1> before = hermite_between<1>(at.s, at.acceleration, after_step.s, after_step.acceleration, t_event);
    knots_.push_back(knot(before));
    const EventOutcome outcome = law_.on_event(t_event, before.u[0], before.v[0]);
    if (event_observer_) event_observer_({t_event, before.u[0], before.v[0], outcome.rest ? 0.0 : outcome.v});
    rest_ = outcome.rest;
    direction_ = outcome.direction;
    const Sample<1> after{t_event, Vec<1>(outcome.u), Vec<1>(rest_ ? 0.0 : outcome.v)};
    knots_.push_back(knot(after));
    const double remaining = t_target - t_event;
    if (rest_ || remaining <= 1e-12 * dt) {
      knots_.push_back(knot({t_target, after.u, after.v}));
      stepper_dt_ = 0;  // the stepper still follows the old segment past the event: restart it below
      break;
    }
    restart(after, remaining);
    at = knots_.back();
  }
  current_ = knots_.back().s;
  if (!rest_ && stepper_dt_ != dt) restart(current_, dt);  // after a step cut by an event
  return true;
}

void EventTrajectory::row_at(double t, std::span<double> out) const {
  for (size_t i = 1; i < knots_.size(); ++i) {
    const Knot& a = knots_[i - 1];
    const Knot& b = knots_[i];
    if (t > b.s.t && i + 1 < knots_.size()) continue;
    if (b.s.t <= a.s.t) continue;  // the jump at an event
    // A fixed-step scheme computed nothing between its knots: straight lines (core/math/linear_between.hpp).
    if (!info_.mesh.adaptive()) return to_row_(linear_between<1>(a.s, b.s, t), out);
    return to_row_(hermite_between<1>(a.s, a.acceleration, b.s, b.acceleration, t), out);
  }
  to_row_(knots_.back().s, out);
}

}  // namespace vibra
