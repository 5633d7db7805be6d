// The caption of a run: its model, scheme and settings as facts, made safe for Pango markup.
#pragma once
#include <string>
#include <utility>
#include <vector>

#include "core/input/parameters.hpp"
#include "core/time_mesh.hpp"

namespace vibra::scenes {

/// A user's text made safe inside Pango markup (formulas may hold < or &).
std::string markup_escaped(const std::string& text);

/// One line of Pango markup describing a run: the settings given (time
/// keys aside, as dt stands for them) with their units, dt and the scheme,
/// e.g. "m = 1 kg · k = 4 N/m · Δt = 0.05 s · rk4" ("Θ = 40° · α = 0.4 ·
/// Δt = 0.1047 · rk4" for the scaled pendulum, whose time has no unit).
std::string run_caption(const std::string& model, const Parameters&, const TimeMesh&);

/// The settings given, with their units, joined as a caption's facts
/// ("<i>m</i> = 1 kg · <i>k</i> = 4 N/m"), leaving out the time keys and `except`.
std::string setting_facts(const Parameters&, const std::string& except = "");
/// "Δ<i>t</i> = 0.05 s": dt in the model's unit of time (none for a scaled model).
std::string dt_fact(const std::string& model, double dt);

/// The same run as (name, value) rows for a page's table, each key once:
/// model, scheme, dt and T as resolved, then the other settings given.
std::vector<std::pair<std::string, std::string>> run_facts(const std::string& model, const Parameters&, const TimeMesh&);

}  // namespace vibra::scenes
