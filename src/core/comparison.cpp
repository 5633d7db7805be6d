// Comparisons (--compare KEY=V1,V2,...): one run per value of one key.
#include "core/comparison.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "core/input/name_spelling.hpp"

namespace vibra {

namespace {
std::string trimmed(std::string_view s) {
  const auto first = s.find_first_not_of(" \t");
  if (first == std::string_view::npos) return "";
  return std::string(s.substr(first, s.find_last_not_of(" \t") - first + 1));
}
}  // namespace

bool is_time_key(const std::string& key) {
  for (const char* time_key : {"scheme", "dt", "steps_per_period", "T", "periods"})
    if (same_name(key, time_key)) return true;
  return false;
}

ComparisonRequest parse_comparison(std::string_view text) {
  const auto eq = text.find('=');
  const std::string whole(text);
  if (eq == std::string_view::npos || trimmed(text.substr(0, eq)).empty())
    throw UsageError("'--compare " + whole + "' is not KEY=V1,V2,...: write e.g. --compare scheme=forward-euler,rk4");
  ComparisonRequest request{trimmed(text.substr(0, eq)), {}};
  std::string_view rest = text.substr(eq + 1);
  while (true) {
    const auto comma = rest.find(',');
    const std::string value = trimmed(rest.substr(0, comma));
    if (value.empty())
      throw UsageError("empty value in '--compare " + whole + "': list the values of " + request.key +
                       " separated by commas, e.g. " + request.key + "=V1,V2");
    if (std::find(request.values.begin(), request.values.end(), value) != request.values.end())
      throw UsageError(request.key + "=" + value + " is given twice in '--compare " + whole + "': list each value once");
    request.values.push_back(value);
    if (comma == std::string_view::npos) break;
    rest = rest.substr(comma + 1);
  }
  if (request.values.size() > kMaxComparisonMembers)
    throw UsageError("--compare has " + std::to_string(request.values.size()) + " values of " + request.key +
                     ": compare at most " + std::to_string(kMaxComparisonMembers) + " at once");
  return request;
}

std::vector<Parameters> comparison_members(const Parameters& base, const ComparisonRequest& request) {
  // given() names an unknown key and the closest valid one.
  if (base.given(request.key))
    throw UsageError(request.key + " is given both in --set and in --compare: drop --set " + request.key);
  std::vector<Parameters> members;
  for (const auto& value : request.values) {
    members.push_back(base);
    members.back().set(request.key, value);
  }
  return members;
}

Comparison::Comparison(const ModelDefinition& model, const Parameters& base, ComparisonRequest request)
    : model_(&model), request_(std::move(request)) {
  std::vector<std::string> keys;
  for (const KeySpec& spec : base.specs()) keys.push_back(spec.name);
  request_.key = listed_spelling(request_.key, keys);  // labels spell the key as --help does
  for (Parameters& p : comparison_members(base, request_)) {
    auto trajectory = model.build(p);
    row_.resize(std::max(row_.size(), trajectory->width()));
    members_.push_back({std::move(p), std::move(trajectory)});
  }
}

std::string Comparison::label(size_t i) const {
  return request_.key == "scheme" ? value(i) : request_.key + " = " + value(i);
}

double Comparison::end_time() const {
  double T = 0;
  for (const Member& m : members_) T = std::max(T, m.trajectory->info().mesh.T);
  return T;
}

namespace {
/// How a run's main quantity grows: its largest |u| over the first and the
/// last quarter of the run and over all of it, from a run of its own.
struct Swing {
  double first = 0, last = 0, all = 0;
  bool overflowed = false;
  /// How much larger its swings end than they start.
  double growth() const { return first > 0 ? last / first : last > 0 ? INFINITY : 1; }
};

Swing swing_of(const ModelDefinition& model, const Parameters& p) {
  std::unique_ptr<Trajectory> run = model.build(p);
  const double T = run->info().mesh.T;
  std::vector<double> row(run->width());
  Swing s;
  try {
    do {
      run->row(row);
      const double u = std::abs(row[1]);
      if (!std::isfinite(u)) return s.overflowed = true, s;
      s.all = std::max(s.all, u);
      if (row[0] <= T / 4) s.first = std::max(s.first, u);
      if (row[0] >= 3 * T / 4) s.last = std::max(s.last, u);
    } while (run->advance());
  } catch (const SolutionError&) {
    s.overflowed = true;
  }
  return s;
}
}  // namespace

void Comparison::set_view_limits() {
  double bound = 0;
  for (const Member& m : members_) bound = std::max(bound, m.trajectory->info().amplitude_bound);
  if (!std::isfinite(end_time())) {  // no whole run to look at: twice what energy allows
    set_escape_limit(bound > 0 ? 2 * bound : INFINITY);
    return;
  }
  std::vector<Swing> swings;
  double calmest = INFINITY;
  for (const Member& m : members_) {
    swings.push_back(swing_of(*model_, m.parameters));
    if (!swings.back().overflowed) calmest = std::min(calmest, swings.back().growth());
  }
  // Growing without bound: overflowing, or swings ending well over twice as
  // wide as they start and growing more than twice as fast as the calmest run.
  auto unbounded = [&](const Swing& s) { return s.overflowed || (s.growth() > 2 && s.growth() > 2 * calmest); };
  double held = bound;
  for (const Swing& s : swings)
    if (!unbounded(s)) held = std::max(held, s.all);
  for (size_t i = 0; i < members_.size(); ++i)
    members_[i].view_limit = unbounded(swings[i]) && held > 0 ? 2 * held : INFINITY;
}

bool Comparison::escaped(Member& m, std::span<const double> row) {
  if (std::abs(row[1]) <= m.view_limit) return false;
  m.early_end = std::isfinite(row[1]) ? EarlyEnd::left_view : EarlyEnd::blew_up;
  m.blow_up_time = row[0];
  return true;
}

void Comparison::advance_to(double t, const Observer& observer) {
  for (size_t i = 0; i < members_.size(); ++i) {
    Member& m = members_[i];
    Trajectory& run = *m.trajectory;
    const std::span<double> row(row_.data(), run.width());
    if (!m.reported_start) {
      m.reported_start = true;
      run.row(row);
      if (observer) observer(i, row);
      if (escaped(m, row)) continue;
    }
    while (m.early_end == EarlyEnd::none && run.t() < t && !run.done()) {
      try {
        run.advance();
      } catch (const SolutionError&) {  // non-finite: this member stops, the others go on
        m.early_end = EarlyEnd::blew_up, m.blow_up_time = run.t() + run.info().mesh.dt;
        break;
      }
      run.row(row);
      if (observer) observer(i, row);
      escaped(m, row);
    }
  }
}

void Comparison::row_at(size_t i, double t, std::span<double> out) const { members_.at(i).trajectory->row_at(t, out); }

}  // namespace vibra
