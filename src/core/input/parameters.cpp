// Parameters: a model's --set keys with units and defaults, parsed from KEY=VALUE with suggestions.
#include "core/input/parameters.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "core/input/name_spelling.hpp"
#include "core/input/quoted_value.hpp"
#include "core/input/value_ranges.hpp"

namespace vibra {

namespace {
std::string trim(std::string_view s) {
  auto first = s.find_first_not_of(" \t");
  if (first == std::string_view::npos) return "";
  auto last = s.find_last_not_of(" \t");
  return std::string(s.substr(first, last - first + 1));
}

/// Edits between two names, ignoring case: insertions, deletions,
/// substitutions, and two neighbours swapped ("alpah" for "alpha"), each one
/// edit, as a typist makes them (optimal string alignment distance).
size_t edit_distance(std::string_view a, std::string_view b) {
  auto same = [&](size_t i, size_t j) { return std::tolower(a[i]) == std::tolower(b[j]); };
  std::vector<std::vector<size_t>> d(a.size() + 1, std::vector<size_t>(b.size() + 1));
  for (size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
  for (size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
  for (size_t i = 1; i <= a.size(); ++i)
    for (size_t j = 1; j <= b.size(); ++j) {
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + (same(i - 1, j - 1) ? 0 : 1)});
      if (i > 1 && j > 1 && same(i - 1, j - 2) && same(i - 2, j - 1)) d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  return d[a.size()][b.size()];
}
}  // namespace

std::string closest_match(std::string_view word, const std::vector<std::string>& candidates) {
  std::string best;
  size_t best_distance = std::max<size_t>(1, word.size() / 3) + 1;  // accept at most this many edits, minus one
  for (const auto& candidate : candidates) {
    size_t d = edit_distance(word, candidate);
    if (d < best_distance) best_distance = d, best = candidate;
  }
  return best;
}

Parameters::Parameters(std::string owner, std::vector<KeySpec> specs)
    : owner_(std::move(owner)), specs_(std::move(specs)) {}

const KeySpec& Parameters::spec(const std::string& key) const {
  for (const auto& s : specs_)
    if (same_name(s.name, key)) return s;
  std::vector<std::string> names;
  for (const auto& s : specs_) names.push_back(s.name);
  std::string near = closest_match(key, names);
  throw UsageError("unknown key '" + key + "' for " + owner_ +
                   (near.empty() ? "" : ": did you mean '" + near + "'?") + " (--help lists the keys)");
}

void Parameters::assign(std::string_view assignment) {
  auto eq = assignment.find('=');
  if (eq == std::string_view::npos || trim(assignment.substr(0, eq)).empty())
    throw UsageError("'--set " + quoted_value(assignment) + "' is not KEY=VALUE: write e.g. --set dt=0.05");
  set(trim(assignment.substr(0, eq)), trim(assignment.substr(eq + 1)));
}

void Parameters::set(const std::string& given_key, const std::string& given_value) {
  const KeySpec& s = spec(given_key);
  const std::string& key = s.name;  // stored and reported as --help spells it
  if (given_value.empty()) throw UsageError("empty value for " + key + ": write " + key + "=VALUE");
  const std::string value = s.kind == ValueKind::choice ? listed_spelling(given_value, s.choices) : given_value;
  if (s.kind == ValueKind::choice && std::find(s.choices.begin(), s.choices.end(), value) == s.choices.end()) {
    std::string list;
    for (const auto& c : s.choices) list += (list.empty() ? "" : ", ") + c;
    throw UsageError("'" + quoted_value(value) + "' is not a valid " + key + " for " + owner_ + ": choose one of " + list);
  }
  // Parse now, so a bad value is reported where it was given, and not kept.
  Parameters trial = *this;
  trial.values_[key] = value;
  switch (s.kind) {
    case ValueKind::number: trial.ranged(key); break;
    case ValueKind::angle: trial.angle(key); break;
    case ValueKind::formula: trial.formula(key); break;
    case ValueKind::choice:
    case ValueKind::text: break;
  }
  values_[key] = value;
}

bool Parameters::given(const std::string& key) const { return values_.count(spec(key).name) != 0; }

bool Parameters::has_value(const std::string& key) const { return given(key) || !spec(key).default_value.empty(); }

std::string Parameters::text(const std::string& key) const {
  const KeySpec& s = spec(key);
  auto it = values_.find(s.name);
  if (it != values_.end()) return it->second;
  if (s.default_value.empty()) throw UsageError(owner_ + " needs a value for " + key + ": add --set " + key + "=VALUE");
  return s.default_value;
}

double Parameters::ranged(const std::string& key) const {
  const std::string t = text(key);
  return in_range(key, evaluate_constant(key, t), t);
}

double Parameters::number(const std::string& key) const {
  double value = ranged(key);
  if (std::isinf(value)) throw UsageError(key + " must be finite, not " + quoted_value(text(key)));
  return value;
}

double Parameters::positive(const std::string& key, bool allow_inf) const {
  double value = ranged(key);
  if (!(value > 0) || (!allow_inf && std::isinf(value)))
    throw UsageError(key + "=" + quoted_value(text(key)) + " must be a positive" + (allow_inf ? "" : " finite") + " number");
  return value;
}

double Parameters::angle(const std::string& key) const {
  std::string t = text(key);
  double scale = M_PI / 180;
  for (auto [suffix, factor] : {std::pair{"rad", 1.0}, std::pair{"deg", M_PI / 180}}) {
    std::string_view sv(t), sx(suffix);
    if (sv.size() > sx.size() && sv.substr(sv.size() - sx.size()) == sx) {
      t = trim(sv.substr(0, sv.size() - sx.size()));
      scale = factor;
      break;
    }
  }
  double value = evaluate_constant(key, t);
  if (!std::isfinite(value)) throw UsageError(key + " must be a finite angle (degrees, or radians with a rad suffix)");
  return in_range(value_range("angle"), key, value, text(key)) * scale;
}

Expression Parameters::formula(const std::string& key) const { return Expression(key, text(key), spec(key).variables); }

std::string Parameters::choice(const std::string& key) const { return text(key); }

std::vector<std::string> Parameters::given_assignments() const {
  std::vector<std::string> out;
  for (const auto& s : specs_) {
    auto it = values_.find(s.name);
    if (it != values_.end()) out.push_back(s.name + "=" + it->second);
  }
  return out;
}

}  // namespace vibra
