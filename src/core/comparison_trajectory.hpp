// The runs of a comparison as one Trajectory, columns suffixed by member.
#pragma once
#include <string>
#include <vector>

#include "core/comparison.hpp"
#include "core/trajectory.hpp"

namespace vibra {

/// The runs of a comparison as one Trajectory, so that an animation, a page
/// and its CSV treat them like one run. A row is t followed by every member's
/// columns (named `u[rk4]`, `u[dt=0.05]`); its samples are the union of the
/// members' meshes, each member read exactly at its own samples and by its
/// 4th-order interpolation between them, so every member keeps its own scheme
/// and dt. A member that leaves the view (Comparison's escape limit) or turns
/// non-finite reads NaN from its blow-up on, and the others go on.
class ComparisonTrajectory final : public Trajectory {
 public:
  ComparisonTrajectory(const ModelDefinition&, const Parameters& base, ComparisonRequest);

  const Comparison& comparison() const { return comparison_; }
  size_t members() const { return comparison_.size(); }
  /// Where member i's columns (after t) start in a row.
  size_t offset(size_t i) const { return offsets_.at(i); }
  /// Whether member i has a sample of its own at the current time (rather
  /// than being interpolated there): each of its samples is current once.
  bool at_sample(size_t i) const {
    return t_ < members_.at(i).blow_up_time && comparison_.trajectory(i).t() == t_;
  }
  /// When member i left the view or blew up, or infinity.
  double blow_up_time(size_t i) const { return members_.at(i).blow_up_time; }
  /// How each member ended early, so far (shared: it outlives this pass, for
  /// a legend that reads it while drawing).
  std::shared_ptr<const std::vector<EarlyEnd>> early_ends() const { return early_ends_; }

  double t() const override { return t_; }
  long long index() const override { return index_; }
  bool done() const override;
  bool advance() override;
  void row(std::span<double> out) const override { row_at(t_, out); }
  void row_at(double t, std::span<double> out) const override;
  /// Whether any member's rows between its samples follow a curve.
  bool bends_between_samples() const override;
  void hide_runs_between_their_samples(std::span<double> row) const override;
  void straight_samples_ahead(std::vector<std::vector<double>>& out) const override;

 private:
  struct MemberState {
    bool finished = false;  ///< reached its own end: holds its last sample
    double blow_up_time = INFINITY;
    bool running() const { return !finished && blow_up_time == INFINITY; }
  };
  void check_escape(size_t i);

  Comparison comparison_;
  std::vector<size_t> offsets_;
  std::vector<MemberState> members_;
  std::shared_ptr<std::vector<EarlyEnd>> early_ends_;
  mutable std::vector<double> scratch_;
  double t_ = 0;
  long long index_ = 0;
};

}  // namespace vibra
