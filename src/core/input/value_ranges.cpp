// The one table of ranges for every number the user can give: options, scene keys and model keys.
#include "core/input/value_ranges.hpp"

#include <cmath>
#include <cstdio>
#include <string>

#include "core/error.hpp"
#include "core/input/quoted_value.hpp"

namespace vibra {

// Bounds: what a lecture can use, with room to spare, and small enough that
// sizes, frame counts and step counts computed from them stay far from
// overflow and from allocations of more than a few hundred MB.
const std::vector<ValueRange>& value_ranges() {
  static const std::vector<ValueRange> rows = {
      // Model keys.
      {"model number", -1e15, 1e15, false, false, false, "any model number is within 1e15 of 0"},
      {"angle", -1e12, 1e12, false, false, false, "an angle in degrees, e.g. 40, or radians, e.g. 0.7rad"},
      {"dt", 0, 1e9, true, false, false, "e.g. dt=0.05 or dt=2*pi/40"},
      {"steps_per_period", 0, 1e9, true, false, false, "e.g. steps_per_period=60"},
      {"T", 0, 1e15, true, false, true, "e.g. T=20, or T=inf for an endless run"},
      {"periods", 0, 1e15, true, false, true, "e.g. periods=10, or periods=inf for an endless run"},
      // Scene keys (and the options that set them).
      {"fps", 1, 240, false, true, false, "e.g. fps=30 (25 or more plays smoothly)"},
      {"speed", 0, 1e12, false, false, false, "simulated time per second of video, e.g. 2 (0: automatic)"},
      {"video_speed", 0, 1e12, false, false, false, "simulated time per second of video, e.g. 2 (0: automatic)"},
      {"window", 0, 1e15, true, false, false, "e.g. window=10 or window=8periods"},
      {"drag_magnification", 0, 1e6, true, false, false, "e.g. drag_magnification=5"},
      {"exaggerate", 0, 1e4, false, false, false, "e.g. exaggerate=5, 1 for true scale, 0 to choose automatically"},
      // Command-line options.
      {"--at", -1e15, 1e15, false, false, false, "a time of the run, e.g. --at 3.2 or --at pi/2"},
      {"--every", 1, 1e15, false, true, false, "e.g. --every 10"},
      {"--threads", 1, 64, false, true, false, "e.g. --threads 4"},
      {"--jobs", 1, 64, false, true, false, "commands at once, e.g. --jobs 2"},
      {"--crf", 0, 63, false, true, false, "e.g. --crf 23 (lower is better)"},
      {"--orbits", 1, 1e9, false, true, false, "e.g. --orbits 1000"},
      {"--levels", 2, 20, false, true, false, "each level halves dt, e.g. --levels 5"},
      {"--rate", 0, 1e6, false, false, false, "lines per second, e.g. --rate 10 (0: as fast as it computes)"},
      // The Python module's arguments.
      {"chunk", 1, 1 << 24, false, true, false, "rows per chunk, e.g. chunk=65536"},
      {"every", 1, 1e15, false, true, false, "e.g. every=10"},
  };
  return rows;
}

const ValueRange& value_range(std::string_view name) {
  for (const ValueRange& row : value_ranges())
    if (row.name == name) return row;
  return value_ranges().front();  // "model number"
}

namespace {
/// A bound as written exactly: 16777216, 1e+15 (never a rounded 1.67772e+07).
std::string bound(double x) {
  if (x == std::floor(x) && std::abs(x) < 1e9) return std::to_string(static_cast<long long>(x));
  const std::string shortest = short_number(x);
  if (std::stod(shortest) == x) return shortest;
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}
}  // namespace

double in_range(const ValueRange& r, std::string_view name, double value, std::string_view text) {
  const bool inside = std::isinf(value) ? (r.inf_allowed && value > 0)
                                        : (r.lo_excluded ? value > r.lo : value >= r.lo) && value <= r.hi;
  if (inside && (!r.whole || value == std::floor(value))) return value;
  std::string kind = std::string(std::isinf(value) && !r.inf_allowed ? "a finite " : "a ") +
                     (r.lo_excluded && r.lo == 0 ? "positive " : "") + (r.whole ? "whole number " : "number ");
  std::string range = !r.lo_excluded ? bound(r.lo) + ".." + bound(r.hi)
                      : r.lo == 0    ? "at most " + bound(r.hi)
                                     : "above " + bound(r.lo) + " and at most " + bound(r.hi);
  if (r.inf_allowed) range += ", or inf";
  const std::string key(name);
  throw UsageError(key + (key.starts_with("--") ? " " : "=") + quoted_value(text) + " must be " + kind + range + ": " +
                   std::string(r.hint));
}

double in_range(std::string_view name, double value, std::string_view text) {
  return in_range(value_range(name), name, value, text);
}

}  // namespace vibra
