// Parameters: a model's --set keys with units and defaults, parsed from KEY=VALUE with suggestions.
#pragma once
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "core/input/expression.hpp"

namespace vibra {

enum class ValueKind {
  number,      ///< a constant expression: 0.5, 2*pi/40, inf
  angle,       ///< degrees by default, radians with a `rad` suffix: 70, 0.7rad, pi/4 rad
  formula,     ///< an expression in the model's variables, e.g. sin(u)
  choice,      ///< one of a fixed list of words
  text,        ///< a word or a file path, checked by the model (e.g. road = sine or a file)
};

/// One `--set` key: its meaning, unit and default, shown by `--help`.
struct KeySpec {
  std::string name;
  ValueKind kind = ValueKind::number;
  std::string default_value;  ///< as the user would type it; "" = no default (optional key)
  std::string unit;
  std::string meaning;
  std::vector<std::string> choices;    ///< for ValueKind::choice
  std::vector<std::string> variables;  ///< for ValueKind::formula
};

/// KEY=VALUE settings checked against a list of KeySpecs. Values are parsed
/// when read, and every error names the key and how to fix it.
class Parameters {
 public:
  /// `owner` names what the keys belong to in messages, e.g. "model pendulum".
  Parameters(std::string owner, std::vector<KeySpec> specs);

  /// Sets from "KEY=VALUE"; throws UsageError for a malformed assignment or an
  /// unknown key (suggesting the closest valid one).
  void assign(std::string_view assignment);
  void set(const std::string& key, const std::string& value);

  bool given(const std::string& key) const;    ///< set by the user
  bool has_value(const std::string& key) const;  ///< set, or with a default
  std::string text(const std::string& key) const;
  double number(const std::string& key) const;
  /// A number that must be > 0 (and finite unless allow_inf).
  double positive(const std::string& key, bool allow_inf = false) const;
  double angle(const std::string& key) const;  ///< in radians
  Expression formula(const std::string& key) const;
  std::string choice(const std::string& key) const;

  const std::vector<KeySpec>& specs() const { return specs_; }
  const std::string& owner() const { return owner_; }
  /// The keys the user set, as KEY=VALUE, in the order of the specs.
  std::vector<std::string> given_assignments() const;

 private:
  const KeySpec& spec(const std::string& key) const;
  /// The number, checked against its row of the ranges (core/input/value_ranges.hpp).
  double ranged(const std::string& key) const;

  std::string owner_;
  std::vector<KeySpec> specs_;
  std::map<std::string, std::string> values_;
};

/// The candidate nearest to `word` by edit distance, or "" when none is close.
std::string closest_match(std::string_view word, const std::vector<std::string>& candidates);

}  // namespace vibra
