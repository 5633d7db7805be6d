// --segment K/N, or auto from a Slurm or Kubernetes job array: which segment of a render this process draws.
#include "cli/segment_option.hpp"

#include <algorithm>
#include <charconv>
#include <cstdlib>
#include <optional>

#include "core/error.hpp"

namespace vibra::cli {

namespace {
constexpr long long kMostSegments = 1'000'000;

std::optional<long long> whole_number(const std::string& text) {
  long long value = 0;
  const char* end = text.data() + text.size();
  const auto [at, error] = std::from_chars(text.data(), end, value);
  if (text.empty() || error != std::errc() || at != end || value < 0) return std::nullopt;
  return value;
}

/// A variable that must hold a whole number.
std::optional<long long> variable(const EnvironmentLookup& environment, const char* name) {
  const char* value = environment(name);
  if (!value) return std::nullopt;
  const auto number = whole_number(value);
  if (!number)
    throw UsageError(std::string("--segment auto: ") + name + "='" + value +
                     "' is not a whole number: unset it, or give --segment K/N");
  return number;
}

render::FrameSegment checked(const std::string& text, long long index, long long count) {
  if (count < 1 || count > kMostSegments || index >= count)
    throw UsageError("--segment " + text + " gives segment " + std::to_string(index) + " of " + std::to_string(count) +
                     ": K must be 0..N-1 and N 1.." + std::to_string(kMostSegments) +
                     " (e.g. --segment 0/4 for the first of four)");
  return {index, count, 0};
}

render::FrameSegment from_slurm(const EnvironmentLookup& environment) {
  const auto id = variable(environment, "SLURM_ARRAY_TASK_ID");
  const auto count = variable(environment, "SLURM_ARRAY_TASK_COUNT");
  if (!id || !count)
    throw UsageError("--segment auto takes K and N from SLURM_ARRAY_TASK_ID and SLURM_ARRAY_TASK_COUNT, which are not "
                     "set: run it in a job array (sbatch --array=0-3), or give --segment K/N, or auto/N with "
                     "JOB_COMPLETION_INDEX");
  const long long min = variable(environment, "SLURM_ARRAY_TASK_MIN").value_or(0);
  const long long step = std::max(1LL, variable(environment, "SLURM_ARRAY_TASK_STEP").value_or(1));
  if (*id < min || (*id - min) % step != 0)
    throw UsageError("--segment auto: SLURM_ARRAY_TASK_ID=" + std::to_string(*id) + " is not in the array's " +
                     std::to_string(min) + ", " + std::to_string(min + step) + ", ...: give --segment K/N");
  return checked("auto", (*id - min) / step, *count);
}
}  // namespace

render::FrameSegment parse_segment_option(const std::string& text, const EnvironmentLookup& environment) {
  if (text == "auto") return from_slurm(environment);
  const auto slash = text.find('/');
  const auto count = slash == std::string::npos ? std::nullopt : whole_number(text.substr(slash + 1));
  const std::string first = slash == std::string::npos ? "" : text.substr(0, slash);
  if (!count || (first != "auto" && !whole_number(first)))
    throw UsageError("--segment " + text + " is not K/N, auto or auto/N: e.g. --segment 0/4 renders the first quarter");
  if (first != "auto") return checked(text, *whole_number(first), *count);
  if (*count < 1 || *count > kMostSegments)  // N first: the fixes below name K/N
    throw UsageError("--segment " + text + ": N must be 1.." + std::to_string(kMostSegments) +
                     " (e.g. --segment auto/4 for one of four)");
  auto index = variable(environment, "JOB_COMPLETION_INDEX");
  if (!index) index = variable(environment, "SLURM_ARRAY_TASK_ID");
  if (!index)
    throw UsageError("--segment " + text + " takes K from JOB_COMPLETION_INDEX (an indexed job) or SLURM_ARRAY_TASK_ID, "
                     "and neither is set: give --segment K/" + std::to_string(*count));
  return checked(text, *index, *count);
}

}  // namespace vibra::cli
