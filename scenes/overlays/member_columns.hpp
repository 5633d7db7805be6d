// Where a comparison member's columns sit within the comparison's row.
#pragma once
#include <functional>
#include <span>

#include "core/comparison_trajectory.hpp"

namespace vibra::scenes {

/// The widest member row a reading copies on the stack.
inline constexpr size_t kMostMemberColumns = 32;

/// A member's columns within a comparison's row (ComparisonTrajectory: t,
/// then every member's columns): where they start and how many there are
/// with t.
struct MemberColumns {
  size_t offset = 1;
  size_t width = 0;
  /// Member i's columns in the rows of `runs`.
  static MemberColumns of(const ComparisonTrajectory& runs, size_t i) {
    return {runs.offset(i), runs.comparison().trajectory(i).width()};
  }
  /// Copies the member's row (t first) out of the comparison's row into `out` (at least `width` long).
  std::span<const double> slice(std::span<const double> row, std::span<double> out) const;
  /// `value` of a member row, read from a comparison row.
  std::function<double(std::span<const double>)> reading(std::function<double(std::span<const double>)> value) const;
};

}  // namespace vibra::scenes
