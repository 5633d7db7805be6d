#pragma once
#include <string>

namespace vibra::scenes {

/// A card's text in the LaTeX subset (\theta, \alpha, \sin, x^2, u_{n+1},
/// \frac{a}{b}, \left| \right|, \Delta t) as Pango markup: Greek and
/// function names as their characters, variables in italics, <sup> and
/// <sub>, a fraction as a/b. A stand-in that keeps cards readable until the
/// typesetter (render/typeset/) sets them properly. `math`: the whole text
/// is mathematics (an equation); else only what stands between $...$ is.
std::string card_markup(const std::string& latex, bool math);

/// The same text without markup, for subtitles: θ'' + α|θ'|θ' + sin θ = 0.
std::string card_plain_text(const std::string& latex, bool math);

}  // namespace vibra::scenes
