// Where a comparison member's columns sit within the comparison's row.
#include "scenes/overlays/member_columns.hpp"

#include <algorithm>
#include <array>

namespace vibra::scenes {

std::span<const double> MemberColumns::slice(std::span<const double> row, std::span<double> out) const {
  out[0] = row[0];
  std::copy_n(row.begin() + offset, width - 1, out.begin() + 1);
  return out.first(width);
}

std::function<double(std::span<const double>)> MemberColumns::reading(
    std::function<double(std::span<const double>)> value) const {
  return [columns = *this, value = std::move(value)](std::span<const double> row) {
    std::array<double, kMostMemberColumns> member;
    return value(columns.slice(row, member));
  };
}

}  // namespace vibra::scenes
