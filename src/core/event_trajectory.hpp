// Trajectories of piecewise-smooth models: events (turning points, impacts) located between steps.
#pragma once
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "core/scheme.hpp"
#include "core/trajectory.hpp"

namespace vibra {

/// What a piecewise-smooth model says at an event (a turning point under
/// friction, an impact): the state after it, and the law of the next segment.
struct EventOutcome {
  double u = 0, v = 0;
  /// +1 or -1: the sign the event value has inside the next segment.
  double direction = 1;
  bool rest = false;  ///< the body stays at u with v = 0 from now on
};

/// A one-dimensional model whose force law changes at events: between two
/// events the law is smooth and the chosen scheme integrates it; the event is
/// where `event_value(u, v)` comes back to 0 from the segment's side. The
/// law must not depend on t: the scheme restarts its clock at each event.
struct EventLaw {
  /// The smooth law of the current segment (it may read state that
  /// `on_event` changes, through a shared pointer).
  std::shared_ptr<SecondOrderSystem<1>> system;
  /// g(u, v): v for turning points, u for impacts on the ground at u = 0.
  std::function<double(double u, double v)> event_value;
  /// At the event time t with the state (u, v) reached there; sets the law
  /// for the next segment and says what follows.
  std::function<EventOutcome(double t, double u, double v)> on_event;
};

/// The Trajectory of an EventLaw on the mesh t_n = n dt. Each step that
/// crosses an event is cut there: the crossing is located inside the step on
/// the Hermite interpolant (exact for free fall, 6th order otherwise),
/// the law changes, and the scheme restarts from the event for the rest of
/// the step. A naive sign() in the force would chatter about the event and
/// errs by O(dt) at mesh points; this does neither. Frames between steps are
/// interpolated piece by piece, never across an event.
class EventTrajectory final : public Trajectory {
 public:
  using RowFunction = std::function<void(const Sample<1>&, std::span<double>)>;
  /// `start` is what holds at t = 0 (direction of the first segment, or rest).
  EventTrajectory(EventLaw law, double u0, double v0, EventOutcome start, TrajectoryInfo info, RowFunction to_row);

  double t() const override { return current_.t; }
  long long index() const override { return index_; }
  bool advance() override;
  void row(std::span<double> out) const override { to_row_(current_, out); }
  void row_at(double t, std::span<double> out) const override;
  /// Rows between mesh points turn at the events inside a step (v jumps at an impact).
  bool bends_between_samples() const override { return true; }

  /// Every event so far: time and the state before and after it.
  struct Event {
    double t;
    double u, v_before, v_after;
  };
  /// Called for each event as it is found (e.g. `vibra analyze bounces`).
  void on_event(std::function<void(const Event&)> observer) { event_observer_ = std::move(observer); }
  bool at_rest() const { return rest_; }

 private:
  struct Knot {
    Sample<1> s;
    Vec<1> acceleration;
  };
  Knot knot(const Sample<1>& s) const;
  void restart(const Sample<1>& from, double step);
  Sample<1> take_step();

  EventLaw law_;
  RowFunction to_row_;
  std::optional<AnyStepper<1>> stepper_;
  double stepper_dt_ = 0;  ///< the step the stepper takes (less than dt right after an event)
  double direction_ = 1;
  bool rest_ = false;
  long long index_ = 0;
  Sample<1> current_;
  std::vector<Knot> knots_;  ///< the last step's pieces: previous sample, events, current sample
  std::function<void(const Event&)> event_observer_;
};

}  // namespace vibra
