// Pacing: slow motion and pauses over ranges of simulated time (scene key pacing).
#include "scenes/timing/pacing.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>

#include "core/error.hpp"
#include "core/input/quoted_value.hpp"

namespace vibra::scenes {

namespace {
/// A plain decimal number filling `text` (3, 2.5, 1e-2), or NaN.
double number(const std::string& text) {
  double value = NAN;
  const char* end = text.data() + text.size();
  const auto [at, error] = std::from_chars(text.data(), end, value);
  return text.empty() || error != std::errc() || at != end ? NAN : value;
}

std::string shown(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", x);
  return text;
}

std::string quoted(const std::string& text) {
  std::string out = "'";  // built in steps: GCC 12 warns falsely about "'" + string (bug 105329)
  out += quoted_value(text);
  return out += "'";
}

constexpr double kMostFactor = 1000, kLongestPause = 3600;
}  // namespace

void Pacing::add_slow(const std::string& text) {
  const auto colon = text.rfind(':');
  const auto dash = colon == std::string::npos ? std::string::npos : text.find('-', 1);
  const double from = dash < colon ? number(text.substr(0, dash)) : NAN;
  const double to = dash < colon ? number(text.substr(dash + 1, colon - dash - 1)) : NAN;
  const double factor = colon == std::string::npos ? NAN : number(text.substr(colon + 1));
  if (!std::isfinite(from) || !std::isfinite(to) || !std::isfinite(factor))
    throw UsageError("slow motion " + quoted(text) +
                     " is not T0-T1:FACTOR: write e.g. 2-4:4 (simulated times 2 to 4 four times slower)");
  if (from < 0 || to <= from)
    throw UsageError("slow motion " + quoted(text) + ": the range must run forward from t >= 0, e.g. 2-4:4");
  if (!(factor > 0) || factor > kMostFactor)
    throw UsageError("slow motion " + quoted(text) + ": the factor must be above 0 and at most 1000 "
                     "(4: four times slower, 0.5: twice as fast)");
  for (const SlowMotion& s : slow)
    if (from < s.to && s.from < to)
      throw UsageError("slow motion " + quoted(text) + " overlaps " + shown(s.from) + "-" + shown(s.to) + ":" +
                       shown(s.factor) + ": give ranges that do not overlap");
  slow.push_back({from, to, factor});
  std::sort(slow.begin(), slow.end(), [](const SlowMotion& a, const SlowMotion& b) { return a.from < b.from; });
}

void Pacing::add_pause(const std::string& text) {
  const auto colon = text.rfind(':');
  const double at = colon == std::string::npos ? NAN : number(text.substr(0, colon));
  const double seconds = colon == std::string::npos ? NAN : number(text.substr(colon + 1));
  if (!std::isfinite(at) || !std::isfinite(seconds))
    throw UsageError("pause " + quoted(text) + " is not T:SECONDS: write e.g. 3:1 (hold t = 3 for 1 s of video)");
  if (at < 0) throw UsageError("pause " + quoted(text) + ": the time must be 0 or later, e.g. 3:1");
  if (!(seconds > 0) || seconds > kLongestPause)
    throw UsageError("pause " + quoted(text) + ": the seconds must be above 0 and at most 3600, e.g. 3:1");
  for (const Pause& p : pauses)
    if (p.at == at)
      throw UsageError("pause " + quoted(text) + ": t = " + shown(at) + " is already paused: give one pause per time");
  pauses.push_back({at, seconds});
  std::sort(pauses.begin(), pauses.end(), [](const Pause& a, const Pause& b) { return a.at < b.at; });
}

void Pacing::check_inside(double T) const {
  for (const SlowMotion& s : slow)
    if (s.to > T * (1 + 1e-12))
      throw UsageError("slow motion " + shown(s.from) + "-" + shown(s.to) + ":" + shown(s.factor) +
                       " reaches past the run's end T = " + shown(T) + ": end it at most there, or run longer");
  for (const Pause& p : pauses)
    if (p.at > T * (1 + 1e-12))
      throw UsageError("pause " + shown(p.at) + ":" + shown(p.seconds) + " lies past the run's end T = " + shown(T) +
                       ": pause inside [0, T], or run longer");
}

double Pacing::added_seconds(double rate) const {
  double extra = 0;
  for (const SlowMotion& s : slow) extra += (s.to - s.from) / rate * (s.factor - 1);
  for (const Pause& p : pauses) extra += p.seconds;
  return extra;
}

double Pacing::rate_for_length(double T, double seconds) const {
  // seconds = (T + sum (to - from)(factor - 1)) / rate + sum pauses.
  double stretched = T, held = 0;
  for (const SlowMotion& s : slow) stretched += (s.to - s.from) * (s.factor - 1);
  for (const Pause& p : pauses) held += p.seconds;
  if (!(seconds > held) || !(stretched > 0))
    throw UsageError("seconds = " + shown(seconds) + " leaves no time for the motion: the pauses alone take " +
                     shown(held) + " s, so give more seconds or shorter pauses");
  return stretched / (seconds - held);
}

std::string Pacing::describe() const {
  std::string out;
  for (const SlowMotion& s : slow)
    out += (out.empty() ? "" : ", ") + ("slow " + shown(s.from) + "-" + shown(s.to) + ":" + shown(s.factor));
  for (const Pause& p : pauses) out += (out.empty() ? "" : ", ") + ("pause " + shown(p.at) + ":" + shown(p.seconds));
  return out;
}

}  // namespace vibra::scenes
