// The typesetter's symbol table: TeX commands, their Unicode characters and atom classes.
#pragma once
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace vibra::render {

/// TeX's classes of math atoms, which decide the space between neighbours:
/// a binary operator (+) gets a medium space each side, a relation (=) a
/// thick one, a function name (sin) a thin one before an ordinary symbol.
enum class Atom { ord, op, bin, rel, open, close, punct, inner };

/// How a glyph run is set: italic (variables), upright (digits, functions,
/// upright Greek capitals, operators), bold (\mathbf), or text (\text{...},
/// the words of a note).
enum class MathFont { italic, upright, bold, text };

/// A command that stands for one symbol: \alpha, \cdot, \le, \sin, ...
struct MathSymbol {
  std::string_view command;  ///< without the backslash
  std::string_view glyphs;   ///< UTF-8
  Atom atom;
  MathFont font;
};

/// The symbol a command names (Greek letters, operators, relations, arrows,
/// function names), or none.
std::optional<MathSymbol> math_symbol(std::string_view command);

/// Every command the typesetter knows, symbols and structures alike (for
/// messages that suggest the closest one).
const std::vector<std::string>& math_command_names();

/// The class and font of a plain character typed in math: letters italic,
/// digits upright, + and - binary (the minus set as U+2212), = < > relations,
/// brackets opening and closing. Empty glyphs: the character itself. The
/// characters with a meaning of their own (\ { } ^ _ ' $ % & # ~) are the
/// parser's.
MathSymbol math_character(char32_t c);

}  // namespace vibra::render
