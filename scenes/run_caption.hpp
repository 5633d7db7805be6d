#pragma once
#include <string>
#include <utility>
#include <vector>

#include "core/parameters.hpp"
#include "core/time_mesh.hpp"

namespace vibra::scenes {

/// A user's text made safe inside Pango markup (formulas may hold < or &).
std::string markup_escaped(const std::string& text);

/// One line of Pango markup describing a run: model, scheme, dt and the
/// settings the user gave (time keys aside, as dt stands for them), e.g.
/// "pendulum · rk4 · Δt = 0.1047 · Theta=40".
std::string run_caption(const std::string& model, const Parameters&, const TimeMesh&);

/// The same run as (name, value) rows for a page's table, each key once:
/// model, scheme, dt and T as resolved, then the other settings given.
std::vector<std::pair<std::string, std::string>> run_facts(const std::string& model, const Parameters&, const TimeMesh&);

}  // namespace vibra::scenes
