// A parsed formula as plain Unicode text, where no typesetting is possible (subtitles, chapter titles).
#pragma once
#include <string>
#include <string_view>
#include <vector>

#include "render/typeset/formula_parser.hpp"

namespace vibra::render {

/// A parsed formula as plain Unicode text, where no typesetting is possible
/// (subtitles, chapter titles, a player's captions): θ″ + α|θ′|θ′ + sin θ = 0,
/// u₍ₙ₊₁₎ as uₙ₊₁, a fraction as a/b with brackets around a sum. Spaces come
/// where TeX puts them: around binary operators and relations, after a
/// function name, and where the formula asks for one (\mu\,\mathrm{sign}(u')
/// reads −μ sign(u′)). Lines (\\) are separated by '\n'.
std::string formula_plain_text(const Formula&);

/// Text with $math$ inside (parse_rich_text) as plain text.
std::string rich_text_plain(const std::vector<RichRun>&);

/// Parses and converts in one go; throws UsageError for bad LaTeX.
std::string formula_plain_text(std::string_view source);
std::string rich_text_plain(std::string_view text);

}  // namespace vibra::render
