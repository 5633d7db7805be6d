// The one table of ranges for every number the user can give: options, scene keys and model keys.
#pragma once
#include <string>
#include <string_view>
#include <vector>

namespace vibra {

/// The range of one number the user can give: a command-line option
/// (`--every`), a scene key (`fps`) or a model key (`dt`). Every number is
/// checked against this one table (value_ranges.cpp) where it is read, so
/// that no extreme value reaches code that was not written for it; what is
/// outside is refused with one line naming the range (docs/reliability.md).
struct ValueRange {
  std::string_view name;  ///< as the user writes it: "fps", "--every", "chunk"
  double lo, hi;
  bool lo_excluded = false;  ///< (lo, hi] instead of [lo, hi]
  bool whole = false;        ///< whole numbers only
  bool inf_allowed = false;  ///< +inf is a value too (T=inf: an endless run)
  std::string_view hint;     ///< the fix, e.g. "e.g. fps=30 (25 or more plays smoothly)"
};

/// Every row of the table, for docs and tests.
const std::vector<ValueRange>& value_ranges();

/// The row for `name`; a model key without a row of its own gets the row for
/// any model number ("model number"), an angle key the row "angle".
const ValueRange& value_range(std::string_view name);

/// `value` (read from `text`) if it lies in `name`'s range; else throws
/// UsageError: "NAME=TEXT must be a number in LO..HI: HINT".
double in_range(std::string_view name, double value, std::string_view text);
/// The same for a row found by the caller (e.g. "angle" for key Theta).
double in_range(const ValueRange& range, std::string_view name, double value, std::string_view text);

}  // namespace vibra
