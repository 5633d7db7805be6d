// What the pictures of a comparison (`plot --compare`, `render --compare`) call its members, as Pango markup.
#pragma once
#include <string>

#include "core/comparison.hpp"
#include "render/draw/color.hpp"

namespace vibra::scenes {

/// A key as the reader knows it: Δt for dt.
std::string key_markup(const std::string& key);

/// A member's legend entry: the scheme's name, or "Δt = 0.05".
std::string member_markup(const Comparison&, size_t member);

/// Member i's colour in a drawing whose body colour is `first`: that for the
/// first member, the palette's for the others: orange, sky blue, green,
/// purple, then vermillion (the first force's arrow), ink and yellow.
render::Color member_color(const render::Color& first, size_t i);

/// "left the view at t = 12.3" (still finite, past its view limit) or
/// "blew up at t = 12.3" (non-finite), for a member's legend entry.
std::string early_end_note(EarlyEnd, double t);

/// One line for a comparison: the model, what its members share (scheme, dt,
/// the settings given) and the key compared.
std::string comparison_caption(const std::string& model, const Comparison&);

}  // namespace vibra::scenes
