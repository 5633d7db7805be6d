// Comparisons (--compare KEY=V1,V2,...): one run per value of one key.
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

/// How a member's run ended before its end time: it left the view (its main
/// quantity passed its view limit, still finite) or blew up (a value turned
/// non-finite or overflowed).
enum class EarlyEnd { none, left_view, blew_up };

/// The runs of a comparison, advanced in lock step on one time axis: each
/// member keeps its own scheme and dt, and any time t can be read from all of
/// them. A member whose main quantity passes its view limit "leaves the
/// view", one whose solution turns non-finite "blows up": either stops there,
/// and the others go on.
/// Static figures read every sample (advance_to with an observer); animations
/// advance to each frame's time and read every member with row_at.
class Comparison {
 public:
  /// Builds every member (throws UsageError as the model does for bad settings).
  Comparison(const ModelDefinition&, const Parameters& base, ComparisonRequest);
  Comparison(Comparison&&) = default;

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

  /// Every member leaves the view when |main quantity| exceeds `limit`
  /// (default: never; only non-finite values stop it).
  void set_escape_limit(double limit) {
    for (Member& m : members_) m.view_limit = limit;
  }
  /// Member i's view limit.
  double escape_limit(size_t i) const { return members_.at(i).view_limit; }
  /// Whether member i's row is outside the view: its main quantity is beyond
  /// the member's view limit (or not finite).
  bool leaves_view(size_t i, std::span<const double> row) const {
    return !(std::abs(row[1]) <= members_.at(i).view_limit);
  }
  /// The limits every picture of a comparison uses: a view holds every run
  /// that stays bounded and lets go only of unbounded growth. Each member is
  /// run once beforehand: one that overflows, or whose swings end more than
  /// twice as wide as they start and grow more than twice as fast as the
  /// calmest member's, grows without bound and leaves the view at twice the
  /// largest |u| of the others (or of what energy allows); every other member
  /// has no limit. So Forward Euler is seen gaining energy before it leaves,
  /// while a run that swings wide but stays bounded, or a resonance that every
  /// member shares, stays in view.
  void set_view_limits();
  /// Whether member i ended early, and why.
  EarlyEnd early_end(size_t i) const { return members_.at(i).early_end; }
  bool blew_up(size_t i) const { return members_.at(i).early_end != EarlyEnd::none; }
  /// When member i left the view or blew up.
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
    EarlyEnd early_end = EarlyEnd::none;
    double blow_up_time = 0;
    double view_limit = INFINITY;
  };
  bool escaped(Member&, std::span<const double> row);

  const ModelDefinition* model_;
  ComparisonRequest request_;
  std::vector<Member> members_;
  std::vector<double> row_;
};

}  // namespace vibra
