#pragma once
#include <cmath>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/models/model.hpp"

namespace vibra {

/// `--compare KEY=V1,V2,...`: one run per value of one key.
struct ComparisonRequest {
  std::string key;
  std::vector<std::string> values;
};

/// At most this many members: more curves than a legend and a palette can tell apart.
inline constexpr size_t kMaxComparisonMembers = 8;

/// Whether a key sets how a problem is solved (scheme, dt, steps_per_period,
/// T, periods) rather than the problem itself.
bool is_time_key(const std::string& key);

/// Parses "KEY=V1,V2,..." (spaces around items ignored). Throws UsageError for
/// a missing '=', an empty value, a value given twice, or more than 8 values.
ComparisonRequest parse_comparison(std::string_view text);

/// The members' settings: `base` with KEY=VALUE for each value, in order.
/// Throws UsageError when the key is unknown (naming the closest one), is
/// already set in `base`, or a value is invalid for it.
std::vector<Parameters> comparison_members(const Parameters& base, const ComparisonRequest&);

/// The runs of a comparison, advanced in lock step on one time axis: each
/// member keeps its own scheme and dt, and any time t can be read from all of
/// them. A member whose solution turns non-finite, or whose main quantity
/// leaves the escape limit, "blows up": it stops there, and the others go on.
/// Static figures read every sample (advance_to with an observer); animations
/// advance to each frame's time and read every member with row_at.
class Comparison {
 public:
  /// Builds every member (throws UsageError as the model does for bad settings).
  Comparison(const ModelDefinition&, const Parameters& base, ComparisonRequest);

  size_t size() const { return members_.size(); }
  const ComparisonRequest& request() const { return request_; }
  const std::string& value(size_t i) const { return request_.values.at(i); }
  /// "rk4" when comparing schemes, "dt = 0.05" for any other key.
  std::string label(size_t i) const;
  /// Whether every member solves one problem (the key is a time key): then
  /// they share one exact solution.
  bool same_problem() const { return is_time_key(request_.key); }
  const Parameters& parameters(size_t i) const { return members_.at(i).parameters; }
  const Trajectory& trajectory(size_t i) const { return *members_.at(i).trajectory; }
  /// A member's run, to be stepped by a caller that keeps its own lock step
  /// (ComparisonTrajectory); do not mix with advance_to.
  Trajectory& trajectory(size_t i) { return *members_.at(i).trajectory; }

  /// A member blows up when |main quantity| exceeds `limit` (default: never;
  /// only non-finite values stop it).
  void set_escape_limit(double limit) { escape_limit_ = limit; }
  double escape_limit() const { return escape_limit_; }
  /// Whether a member's row has left the view: its main quantity is beyond
  /// the escape limit or not finite.
  bool leaves_view(std::span<const double> row) const { return !(std::abs(row[1]) <= escape_limit_); }
  /// The limit every picture of a comparison uses: twice the largest
  /// amplitude the members can reach (from their energy), so that a scheme
  /// that gains energy is seen doing it before it leaves the view; no limit
  /// when no member knows its bound.
  void set_escape_limit_from_bounds();
  bool blew_up(size_t i) const { return members_.at(i).blew_up; }
  double blow_up_time(size_t i) const { return members_.at(i).blow_up_time; }
  /// Where the last member ends (members may differ in T).
  double end_time() const;

  /// Per sample of a member: its index and its row (the model's columns).
  using Observer = std::function<void(size_t member, std::span<const double> row)>;
  /// Advances every running member until it reaches time t (its first sample
  /// at or after t) or its end, telling `observer` each new sample; the first
  /// call also tells the initial samples.
  void advance_to(double t, const Observer& observer = {});
  /// A member's columns at time t, within its current step (after advance_to(t)),
  /// by the trajectory's 4th-order interpolation.
  void row_at(size_t i, double t, std::span<double> out) const;

 private:
  struct Member {
    Parameters parameters;
    std::unique_ptr<Trajectory> trajectory;
    bool reported_start = false;
    bool blew_up = false;
    double blow_up_time = 0;
  };
  bool escaped(Member&, std::span<const double> row);

  ComparisonRequest request_;
  std::vector<Member> members_;
  std::vector<double> row_;
  double escape_limit_ = INFINITY;
};

}  // namespace vibra
