#include "scenes/lecture/card_text.hpp"

#include <cctype>
#include <map>

namespace vibra::scenes {

namespace {
const std::map<std::string, std::string>& symbols() {
  static const std::map<std::string, std::string> table = {
      {"alpha", "α"},  {"beta", "β"},   {"gamma", "γ"},  {"delta", "δ"},   {"epsilon", "ε"}, {"zeta", "ζ"},
      {"eta", "η"},    {"theta", "θ"},  {"iota", "ι"},   {"kappa", "κ"},   {"lambda", "λ"},  {"mu", "μ"},
      {"nu", "ν"},     {"xi", "ξ"},     {"pi", "π"},     {"rho", "ρ"},     {"sigma", "σ"},   {"tau", "τ"},
      {"phi", "φ"},    {"chi", "χ"},    {"psi", "ψ"},    {"omega", "ω"},   {"Gamma", "Γ"},   {"Delta", "Δ"},
      {"Theta", "Θ"},  {"Lambda", "Λ"}, {"Pi", "Π"},     {"Sigma", "Σ"},   {"Phi", "Φ"},     {"Psi", "Ψ"},
      {"Omega", "Ω"},  {"cdot", "·"},   {"times", "×"},  {"approx", "≈"},  {"le", "≤"},      {"ge", "≥"},
      {"leq", "≤"},    {"geq", "≥"},    {"ne", "≠"},     {"to", "→"},      {"infty", "∞"},   {"pm", "±"},
      {"partial", "∂"}, {"quad", " "},  {"qquad", "  "},
  };
  return table;
}

bool is_function(const std::string& name) {
  for (const char* f : {"sin", "cos", "tan", "exp", "ln", "log", "sinh", "cosh", "tanh", "sign", "sgn"})
    if (name == f) return true;
  return false;
}

class Converter {
 public:
  Converter(const std::string& text, bool markup, bool math) : s_(text), markup_(markup), math_(math) {}

  std::string run() {
    std::string out;
    while (i_ < s_.size()) out += item();
    return out;
  }

 private:
  std::string escaped(char c) const {
    if (!markup_) return std::string(1, c);
    if (c == '&') return "&amp;";
    if (c == '<') return "&lt;";
    if (c == '>') return "&gt;";
    return std::string(1, c);
  }
  std::string tag(const char* name, const std::string& inner) const {
    return markup_ ? std::string("<") + name + ">" + inner + "</" + name + ">" : inner;
  }
  /// One group: {...} or a single item.
  std::string group() {
    if (i_ < s_.size() && s_[i_] == '{') {
      ++i_;
      std::string out;
      while (i_ < s_.size() && s_[i_] != '}') out += item();
      if (i_ < s_.size()) ++i_;
      return out;
    }
    return i_ < s_.size() ? item() : "";
  }
  std::string item() {
    const char c = s_[i_];
    if (c == '\\') return command();
    if (c == '{' && math_) return group();
    if (c == '$') return ++i_, math_ = !math_, "";
    if (c == '}') return ++i_, "";
    if (!math_) return ++i_, escaped(c);
    if (c == '^' || c == '_') {
      ++i_;
      const std::string inner = group();
      if (markup_) return tag(c == '^' ? "sup" : "sub", inner);
      return std::string(1, c) + (inner.size() > 1 ? "(" + inner + ")" : inner);
    }
    if (std::isalpha(static_cast<unsigned char>(c))) {
      std::string word;
      while (i_ < s_.size() && std::isalpha(static_cast<unsigned char>(s_[i_]))) word += s_[i_++];
      return tag("i", word);
    }
    ++i_;
    return escaped(c);
  }
  std::string command() {
    ++i_;  // the backslash
    std::string name;
    while (i_ < s_.size() && std::isalpha(static_cast<unsigned char>(s_[i_]))) name += s_[i_++];
    if (name.empty()) {  // \, \; \! \\ and escaped characters
      if (i_ >= s_.size()) return "";
      const char c = s_[i_++];
      if (c == '\\') return "\n";
      if (c == ',' || c == ';' || c == ' ') return "\u2009";
      if (c == '!') return "";
      return escaped(c);
    }
    if (name == "frac") {
      const std::string a = group(), b = group();
      return (a.size() > 1 ? "(" + a + ")" : a) + "/" + (b.size() > 1 ? "(" + b + ")" : b);
    }
    if (name == "left" || name == "right") return "";
    if (name == "mathrm" || name == "text" || name == "operatorname") {
      std::string saved = group();
      return saved;
    }
    if (is_function(name)) return name + "\u2009";
    const auto symbol = symbols().find(name);
    if (symbol != symbols().end()) return symbol->second;
    return escaped('\\') + name;  // unknown: shown as written
  }

  const std::string& s_;
  bool markup_, math_;
  std::size_t i_ = 0;
};
}  // namespace

std::string card_markup(const std::string& latex, bool math) { return Converter(latex, true, math).run(); }
std::string card_plain_text(const std::string& latex, bool math) { return Converter(latex, false, math).run(); }

}  // namespace vibra::scenes
