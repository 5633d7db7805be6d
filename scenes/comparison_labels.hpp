#pragma once
#include <string>

#include "core/comparison.hpp"

namespace vibra::scenes {

// What the pictures of a comparison (`plot --compare`, `render --compare`)
// call its members, as Pango markup.

/// A key as the reader knows it: Δt for dt.
std::string key_markup(const std::string& key);

/// A member's legend entry: the scheme's name, or "Δt = 0.05".
std::string member_markup(const Comparison&, size_t member);

/// ": blew up at t = 12.3", appended to a member's legend entry.
std::string blow_up_note(double t);

/// One line for a comparison: the model, what its members share (scheme, dt,
/// the settings given) and the key compared.
std::string comparison_caption(const std::string& model, const Comparison&);

}  // namespace vibra::scenes
