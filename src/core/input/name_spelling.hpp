// The one spelling rule for names vibra looks up (scenes, models, schemes, keys, diagrams, options): a hyphen and an underscore are the same letter.
#pragma once
#include <string>
#include <string_view>
#include <vector>

namespace vibra {

/// `name` as names are compared: every '-' read as '_' ("elastic-pendulum"
/// and "elastic_pendulum" both give "elastic_pendulum").
std::string name_key(std::string_view name);

/// Whether `a` and `b` name the same thing under the rule.
bool same_name(std::string_view a, std::string_view b);

/// The entry of `names` that `name` spells, in the entry's own spelling, or
/// `name` unchanged when none does (its lookup then reports it as unknown).
std::string listed_spelling(std::string_view name, const std::vector<std::string>& names);

}  // namespace vibra
