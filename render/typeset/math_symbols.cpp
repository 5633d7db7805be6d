// The typesetter's symbol table: TeX commands, their Unicode characters and atom classes.
#include "render/typeset/math_symbols.hpp"

#include <array>

namespace vibra::render {

namespace {
using enum Atom;
constexpr MathFont I = MathFont::italic, U = MathFont::upright;

// Lowercase Greek is italic and uppercase upright, as TeX sets them.
constexpr std::array kSymbols = {
    MathSymbol{"alpha", "α", ord, I},    MathSymbol{"beta", "β", ord, I},       MathSymbol{"gamma", "γ", ord, I},
    MathSymbol{"delta", "δ", ord, I},    MathSymbol{"epsilon", "ϵ", ord, I},    MathSymbol{"varepsilon", "ε", ord, I},
    MathSymbol{"zeta", "ζ", ord, I},     MathSymbol{"eta", "η", ord, I},        MathSymbol{"theta", "θ", ord, I},
    MathSymbol{"vartheta", "ϑ", ord, I}, MathSymbol{"iota", "ι", ord, I},       MathSymbol{"kappa", "κ", ord, I},
    MathSymbol{"lambda", "λ", ord, I},   MathSymbol{"mu", "μ", ord, I},         MathSymbol{"nu", "ν", ord, I},
    MathSymbol{"xi", "ξ", ord, I},       MathSymbol{"pi", "π", ord, I},         MathSymbol{"varpi", "ϖ", ord, I},
    MathSymbol{"rho", "ρ", ord, I},      MathSymbol{"varrho", "ϱ", ord, I},     MathSymbol{"sigma", "σ", ord, I},
    MathSymbol{"varsigma", "ς", ord, I}, MathSymbol{"tau", "τ", ord, I},        MathSymbol{"upsilon", "υ", ord, I},
    MathSymbol{"phi", "ϕ", ord, I},      MathSymbol{"varphi", "φ", ord, I},     MathSymbol{"chi", "χ", ord, I},
    MathSymbol{"psi", "ψ", ord, I},      MathSymbol{"omega", "ω", ord, I},
    MathSymbol{"Gamma", "Γ", ord, U},    MathSymbol{"Delta", "Δ", ord, U},      MathSymbol{"Theta", "Θ", ord, U},
    MathSymbol{"Lambda", "Λ", ord, U},   MathSymbol{"Xi", "Ξ", ord, U},         MathSymbol{"Pi", "Π", ord, U},
    MathSymbol{"Sigma", "Σ", ord, U},    MathSymbol{"Upsilon", "Υ", ord, U},    MathSymbol{"Phi", "Φ", ord, U},
    MathSymbol{"Psi", "Ψ", ord, U},      MathSymbol{"Omega", "Ω", ord, U},
    // Binary operators and relations.
    MathSymbol{"cdot", "·", bin, U},     MathSymbol{"times", "×", bin, U},      MathSymbol{"pm", "±", bin, U},
    MathSymbol{"mp", "∓", bin, U},       MathSymbol{"div", "÷", bin, U},        MathSymbol{"approx", "≈", rel, U},
    MathSymbol{"le", "≤", rel, U},       MathSymbol{"leq", "≤", rel, U},        MathSymbol{"ge", "≥", rel, U},
    MathSymbol{"geq", "≥", rel, U},      MathSymbol{"ne", "≠", rel, U},         MathSymbol{"neq", "≠", rel, U},
    MathSymbol{"equiv", "≡", rel, U},    MathSymbol{"sim", "∼", rel, U},        MathSymbol{"propto", "∝", rel, U},
    MathSymbol{"ll", "≪", rel, U},       MathSymbol{"gg", "≫", rel, U},         MathSymbol{"to", "→", rel, U},
    MathSymbol{"rightarrow", "→", rel, U}, MathSymbol{"leftarrow", "←", rel, U}, MathSymbol{"mapsto", "↦", rel, U},
    MathSymbol{"Rightarrow", "⇒", rel, U}, MathSymbol{"in", "∈", rel, U},
    // Ordinary symbols.
    MathSymbol{"infty", "∞", ord, U},    MathSymbol{"partial", "∂", ord, U},    MathSymbol{"nabla", "∇", ord, U},
    MathSymbol{"prime", "′", ord, U},    MathSymbol{"ell", "ℓ", ord, U},        MathSymbol{"hbar", "ℏ", ord, U},
    MathSymbol{"degree", "°", ord, U},   MathSymbol{"ldots", "…", inner, U},    MathSymbol{"dots", "…", inner, U},
    MathSymbol{"cdots", "⋯", inner, U},  MathSymbol{"sum", "∑", op, U},         MathSymbol{"int", "∫", op, U},
    MathSymbol{"prod", "∏", op, U},
    // Function names: upright, with a thin space before an ordinary symbol.
    MathSymbol{"sin", "sin", op, U},     MathSymbol{"cos", "cos", op, U},       MathSymbol{"tan", "tan", op, U},
    MathSymbol{"cot", "cot", op, U},     MathSymbol{"sec", "sec", op, U},       MathSymbol{"csc", "csc", op, U},
    MathSymbol{"exp", "exp", op, U},     MathSymbol{"ln", "ln", op, U},         MathSymbol{"log", "log", op, U},
    MathSymbol{"sinh", "sinh", op, U},   MathSymbol{"cosh", "cosh", op, U},     MathSymbol{"tanh", "tanh", op, U},
    MathSymbol{"arcsin", "arcsin", op, U}, MathSymbol{"arccos", "arccos", op, U}, MathSymbol{"arctan", "arctan", op, U},
    MathSymbol{"max", "max", op, U},     MathSymbol{"min", "min", op, U},       MathSymbol{"sgn", "sgn", op, U},
    MathSymbol{"det", "det", op, U},     MathSymbol{"lim", "lim", op, U},
};

// Structures and spacing, parsed by the parser itself (formula_parser.cpp).
constexpr std::array<std::string_view, 27> kStructures = {
    "frac", "dfrac", "tfrac", "sqrt", "left", "right", "text", "mathrm", "mathbf", "mathit", "operatorname",
    "dot", "ddot", "hat", "bar", "tilde", "vec", "quad", "qquad", ",", ";", ":", "!", "langle", "rangle", "|", "\\"};
}  // namespace

std::optional<MathSymbol> math_symbol(std::string_view command) {
  for (const MathSymbol& s : kSymbols)
    if (s.command == command) return s;
  return std::nullopt;
}

const std::vector<std::string>& math_command_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> all;
    for (const MathSymbol& s : kSymbols) all.emplace_back(s.command);
    for (std::string_view s : kStructures)
      if (s.size() > 1) all.emplace_back(s);
    return all;
  }();
  return names;
}

MathSymbol math_character(char32_t c) {
  if ((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z')) return {"", "", ord, I};
  // Greek typed as such: lowercase italic, as its command would be.
  if (c >= 0x3b1 && c <= 0x3c9) return {"", "", ord, I};
  if (c >= '0' && c <= '9') return {"", "", ord, U};
  switch (c) {
    case '+': return {"", "+", bin, U};
    case '-': return {"", "−", bin, U};
    case '*': return {"", "∗", bin, U};
    case '=': return {"", "=", rel, U};
    case '<': return {"", "<", rel, U};
    case '>': return {"", ">", rel, U};
    case ':': return {"", ":", rel, U};
    case '(': return {"", "(", open, U};
    case '[': return {"", "[", open, U};
    case ')': return {"", ")", close, U};
    case ']': return {"", "]", close, U};
    case '!': return {"", "!", close, U};
    case ',': return {"", ",", punct, U};
    case ';': return {"", ";", punct, U};
    case '.': return {"", ".", ord, U};
    case '/': return {"", "/", ord, U};
    case '|': return {"", "|", ord, U};
    case '?': return {"", "?", close, U};
    case '@': return {"", "@", ord, U};
    case '"': return {"", "\"", ord, U};
    default: break;
  }
  // Anything else typed as such (≈, °) is an upright ordinary symbol.
  return {"", "", ord, U};
}

}  // namespace vibra::render
