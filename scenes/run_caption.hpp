#pragma once
#include <string>

#include "core/parameters.hpp"
#include "core/time_mesh.hpp"

namespace vibra::scenes {

/// A user's text made safe inside Pango markup (formulas may hold < or &).
std::string markup_escaped(const std::string& text);

/// One line of Pango markup describing a run: model, scheme, dt and the
/// settings the user gave (time keys aside, as dt stands for them), e.g.
/// "pendulum · rk4 · Δt = 0.1047 · Theta=40".
std::string run_caption(const std::string& model, const Parameters&, const TimeMesh&);

}  // namespace vibra::scenes
