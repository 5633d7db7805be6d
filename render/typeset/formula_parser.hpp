// Parses the LaTeX subset vibra typesets ($...$ in titles, notes and equations) into elements.
#pragma once
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "render/typeset/math_symbols.hpp"

namespace vibra::render {

/// One element of a parsed formula. Rows (`group`) hold elements side by
/// side; the other kinds hold their parts as rows in `parts`.
struct MathNode {
  enum class Kind {
    glyphs,     ///< a symbol or word set in `font`: a variable, a number, an operator, sin
    group,      ///< {...}: `parts` side by side
    fraction,   ///< \frac: parts[0] over parts[1]
    scripts,    ///< parts[0] the base, parts[1] the superscript, parts[2] the subscript (each maybe absent)
    radical,    ///< \sqrt: parts[0] under the sign
    delimited,  ///< \left X ... \right Y: parts[0] between `glyphs` (X) and `close` (Y)
    space,      ///< \, \; \quad: `space` em wide
    accent,     ///< \dot, \hat, ...: parts[0] under the accent `glyphs` (\bar: a rule)
  };
  Kind kind = Kind::group;
  Atom atom = Atom::ord;
  MathFont font = MathFont::upright;
  std::string glyphs;  ///< UTF-8; a delimited node's opening delimiter ("." = none)
  std::string close;   ///< a delimited node's closing delimiter
  double space = 0;    ///< em
  bool has_sup = false, has_sub = false;
  std::vector<MathNode> parts;
};

/// A formula in the LaTeX subset (docs/drawing.md), parsed: its lines
/// (separated by \\), each a row.
struct Formula {
  std::vector<MathNode> lines;
  std::string source;
};

/// Bounds on any input, so that the work is bounded whatever is typed.
inline constexpr std::size_t kMaxFormulaLength = 1000;  ///< bytes of source
inline constexpr int kMaxFormulaDepth = 12;             ///< nested groups, fractions, scripts, radicals

/// Parses a formula. Throws UsageError, one line naming the problem and the
/// fix, for an unknown command, unbalanced braces, a missing argument, a
/// double superscript, nesting deeper than kMaxFormulaDepth, a formula
/// longer than kMaxFormulaLength, or text that is not UTF-8.
Formula parse_formula(std::string_view source);

/// Text with $math$ inside (a note, a title): runs of plain words and of
/// formulas, in order. `\$` is a dollar sign.
struct RichRun {
  bool math = false;
  std::string text;  ///< plain text (math: the source)
  Formula formula;   ///< math runs
};
std::vector<RichRun> parse_rich_text(std::string_view text);

}  // namespace vibra::render
