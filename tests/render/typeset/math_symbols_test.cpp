// The typesetter's symbol table against TeX's classes written out here: each typed character's atom, font and glyph, and the commands' symbols.
#include <catch2/catch.hpp>
#include <algorithm>
#include <string>

#include "render/typeset/math_symbols.hpp"

using namespace vibra::render;

namespace {
struct Typed {
  char32_t c;
  const char* glyphs;  ///< "" when the character is set as itself
  Atom atom;
  MathFont font;
};

// TeX's classes (The TeXbook, chapter 17): + - * binary, = < > : relations,
// ( [ opening, ) ] ! ? closing, , ; punctuation; the minus and star as U+2212 and U+2217.
const Typed kTyped[] = {
    {'x', "", Atom::ord, MathFont::italic},     {'Q', "", Atom::ord, MathFont::italic},
    {U'ω', "", Atom::ord, MathFont::italic},    {'7', "", Atom::ord, MathFont::upright},
    {'+', "+", Atom::bin, MathFont::upright},   {'-', "−", Atom::bin, MathFont::upright},
    {'*', "∗", Atom::bin, MathFont::upright},   {'=', "=", Atom::rel, MathFont::upright},
    {'<', "<", Atom::rel, MathFont::upright},   {'>', ">", Atom::rel, MathFont::upright},
    {':', ":", Atom::rel, MathFont::upright},   {'(', "(", Atom::open, MathFont::upright},
    {'[', "[", Atom::open, MathFont::upright},  {')', ")", Atom::close, MathFont::upright},
    {']', "]", Atom::close, MathFont::upright}, {'!', "!", Atom::close, MathFont::upright},
    {'?', "?", Atom::close, MathFont::upright}, {',', ",", Atom::punct, MathFont::upright},
    {';', ";", Atom::punct, MathFont::upright}, {'.', ".", Atom::ord, MathFont::upright},
    {'/', "/", Atom::ord, MathFont::upright},   {'|', "|", Atom::ord, MathFont::upright},
    {'@', "@", Atom::ord, MathFont::upright},   {'"', "\"", Atom::ord, MathFont::upright},
    {U'Ω', "", Atom::ord, MathFont::upright},   {U'≈', "", Atom::ord, MathFont::upright},
};
}  // namespace

TEST_CASE("each character typed in math has TeX's class, font and glyph", "[typeset]") {
  for (const Typed& t : kTyped) {
    INFO("U+" << std::hex << unsigned(t.c));
    const MathSymbol s = math_character(t.c);
    CHECK(s.glyphs == t.glyphs);
    CHECK(s.atom == t.atom);
    CHECK(s.font == t.font);
  }
}

TEST_CASE("commands name their symbols: lowercase Greek italic, capitals upright, relations and functions", "[typeset]") {
  const auto symbol = [](const char* command) {
    const auto s = math_symbol(command);
    REQUIRE(s);
    return *s;
  };
  CHECK(symbol("omega").glyphs == "ω");
  CHECK(symbol("omega").font == MathFont::italic);
  CHECK(symbol("Omega").glyphs == "Ω");
  CHECK(symbol("Omega").font == MathFont::upright);
  CHECK(symbol("le").glyphs == "≤");
  CHECK(symbol("le").atom == Atom::rel);
  CHECK(symbol("cdot").atom == Atom::bin);
  CHECK(symbol("sin").glyphs == "sin");
  CHECK(symbol("sin").atom == Atom::op);
  CHECK(symbol("ldots").atom == Atom::inner);
  CHECK_FALSE(math_symbol("frac"));  // a structure, parsed by the parser
  CHECK_FALSE(math_symbol("omegaa"));
}

TEST_CASE("the command names for suggestions hold the symbols and the named structures, not the one-character ones",
          "[typeset]") {
  const auto& names = math_command_names();
  const auto has = [&](const std::string& n) { return std::find(names.begin(), names.end(), n) == names.end() ? 0 : 1; };
  CHECK(has("alpha") + has("lim") + has("frac") + has("operatorname") + has("rangle") == 5);
  CHECK(has(",") + has("\\") + has("|") == 0);
}
