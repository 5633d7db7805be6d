// A parsed formula as plain Unicode text, where no typesetting is possible (subtitles, chapter titles).
#include "render/typeset/formula_text.hpp"

#include <map>

namespace vibra::render {

namespace {

/// The text in Unicode's super- or subscript characters, if each of its
/// characters has one (2 -> ², n -> ⁿ, n+1 -> ₙ₊₁), else empty.
std::string scripted(const std::string& text, bool superscript) {
  static const std::map<std::string, std::string> sup = {
      {"0", "⁰"}, {"1", "¹"}, {"2", "²"}, {"3", "³"}, {"4", "⁴"}, {"5", "⁵"}, {"6", "⁶"}, {"7", "⁷"},
      {"8", "⁸"}, {"9", "⁹"}, {"+", "⁺"}, {"-", "⁻"}, {"−", "⁻"}, {"=", "⁼"}, {"(", "⁽"}, {")", "⁾"},
      {"n", "ⁿ"}, {"i", "ⁱ"}};
  static const std::map<std::string, std::string> sub = {
      {"0", "₀"}, {"1", "₁"}, {"2", "₂"}, {"3", "₃"}, {"4", "₄"}, {"5", "₅"}, {"6", "₆"}, {"7", "₇"},
      {"8", "₈"}, {"9", "₉"}, {"+", "₊"}, {"-", "₋"}, {"−", "₋"}, {"=", "₌"}, {"(", "₍"}, {")", "₎"},
      {"a", "ₐ"}, {"e", "ₑ"}, {"o", "ₒ"}, {"x", "ₓ"}, {"h", "ₕ"}, {"k", "ₖ"}, {"l", "ₗ"}, {"m", "ₘ"},
      {"n", "ₙ"}, {"p", "ₚ"}, {"s", "ₛ"}, {"t", "ₜ"}, {"i", "ᵢ"}, {"j", "ⱼ"}, {"r", "ᵣ"}, {"u", "ᵤ"},
      {"v", "ᵥ"}};
  const auto& table = superscript ? sup : sub;
  std::string out;
  for (std::size_t i = 0; i < text.size();) {
    // One UTF-8 character at a time (the minus sign is three bytes).
    std::size_t length = 1;
    const auto lead = static_cast<unsigned char>(text[i]);
    if (lead >= 0xF0) length = 4;
    else if (lead >= 0xE0) length = 3;
    else if (lead >= 0xC0) length = 2;
    if (text[i] == ' ') {
      ++i;
      continue;
    }
    const auto found = table.find(text.substr(i, length));
    if (found == table.end()) return {};
    out += found->second;
    i += length;
  }
  return out;
}

/// The combining character for an accent's glyph (\dot: U+0307 over the
/// letter before it); an unknown accent is written after its base.
std::string combining(const std::string& accent) {
  static const std::map<std::string, std::string> table = {
      {"˙", "\u0307"}, {"¨", "\u0308"}, {"ˆ", "\u0302"}, {"^", "\u0302"}, {"˜", "\u0303"},
      {"~", "\u0303"}, {"→", "\u20D7"}, {"⃗", "\u20D7"}, {"", "\u0304"},  {"¯", "\u0304"}};
  const auto found = table.find(accent);
  return found == table.end() ? accent : found->second;
}

class PlainText {
 public:
  std::string row(const MathNode& group) {
    std::string out;
    bool first = true;
    Atom previous = Atom::open;  // a row's start: a leading minus is a sign, not an operator
    bool after_fraction = false;
    for (const MathNode& node : group.parts) {
      const std::string text = node_text(node);
      if (text.empty() && node.kind != MathNode::Kind::space) continue;
      Atom atom = node.atom;
      // TeX's rule: a binary operator with nothing to its left is a sign.
      if (atom == Atom::bin && (previous == Atom::bin || previous == Atom::rel || previous == Atom::open ||
                                previous == Atom::op || previous == Atom::punct))
        atom = Atom::ord;
      // A fraction written a/b stands apart from its neighbours, so that
      // Δt² g/L sin u does not read as Δt²g/Lsin u.
      const bool fraction = node.kind == MathNode::Kind::fraction;
      const bool spaced = atom == Atom::bin || atom == Atom::rel || previous == Atom::bin || previous == Atom::rel ||
                          (previous == Atom::op && atom != Atom::open && atom != Atom::punct) ||
                          (atom == Atom::op && previous != Atom::open) || previous == Atom::punct || fraction ||
                          after_fraction;
      if (!first && spaced && !out.empty() && out.back() != ' ' && text.front() != ' ') out += ' ';
      out += text;
      first = false;
      previous = atom;
      after_fraction = fraction;
    }
    return out;
  }

 private:
  /// A part as an operand of /, ^ or _: bracketed when it is more than one
  /// symbol, unless it is a function applied to a bracket (tanh(αu)/α).
  std::string operand(const MathNode& part) {
    const std::string text = node_text(part);
    const bool single = part.kind == MathNode::Kind::glyphs ||
                        (part.kind == MathNode::Kind::group && part.parts.size() == 1 &&
                         part.parts[0].kind == MathNode::Kind::glyphs) ||
                        part.kind == MathNode::Kind::delimited || applied_function(part, text);
    return single ? text : "(" + text + ")";
  }

  /// Whether `group` reads "name(...)": an operator's name, then one bracket to its end.
  static bool applied_function(const MathNode& group, const std::string& text) {
    if (group.kind != MathNode::Kind::group || group.parts.size() < 3 || group.parts[0].atom != Atom::op) return false;
    const std::size_t open = group.parts[0].glyphs.size();
    if (open >= text.size() || text[open] != '(' || text.back() != ')') return false;
    int depth = 0;
    for (std::size_t i = open; i < text.size(); ++i) {
      depth += text[i] == '(' ? 1 : text[i] == ')' ? -1 : 0;
      if (depth == 0 && i + 1 < text.size()) return false;  // closed before the end: (a)(b)
    }
    return depth == 0;
  }

  std::string node_text(const MathNode& node) {
    switch (node.kind) {
      case MathNode::Kind::glyphs: return node.glyphs;
      case MathNode::Kind::group: return row(node);
      case MathNode::Kind::fraction: return operand(node.parts[0]) + "/" + operand(node.parts[1]);
      case MathNode::Kind::radical: return "√" + operand(node.parts[0]);
      // Any space the writer asked for reads as one (\mu\,\mathrm{sign}: "μ sign", not "μsign");
      // a negative one (\!) as none.
      case MathNode::Kind::space: return node.space > 0 ? " " : "";
      case MathNode::Kind::delimited: {
        const std::string open = node.glyphs == "." ? "" : node.glyphs;
        const std::string close = node.close == "." ? "" : node.close;
        return open + node_text(node.parts[0]) + close;
      }
      case MathNode::Kind::accent: return node_text(node.parts[0]) + combining(node.glyphs);
      case MathNode::Kind::scripts: {
        std::string out = node.parts.empty() ? "" : node_text(node.parts[0]);
        if (node.has_sub && node.parts.size() > 2) out += script(node.parts[2], false);
        if (node.has_sup && node.parts.size() > 1) out += script(node.parts[1], true);
        return out;
      }
    }
    return {};
  }

  std::string script(const MathNode& part, bool superscript) {
    const std::string text = node_text(part);
    if (superscript && (text.starts_with("′") || text.starts_with("″") || text.starts_with("‴") ||
                        text.starts_with("⁗")))
      return text;  // primes sit on the letter as they are
    if (std::string small = scripted(text, superscript); !small.empty()) return small;
    return (superscript ? "^" : "_") + operand(part);
  }
};

}  // namespace

std::string formula_plain_text(const Formula& formula) {
  std::string out;
  PlainText plain;
  for (const MathNode& line : formula.lines) out += (out.empty() ? "" : "\n") + plain.row(line);
  return out;
}

std::string rich_text_plain(const std::vector<RichRun>& runs) {
  std::string out;
  for (const RichRun& run : runs) out += run.math ? formula_plain_text(run.formula) : run.text;
  return out;
}

std::string formula_plain_text(std::string_view source) { return formula_plain_text(parse_formula(source)); }
std::string rich_text_plain(std::string_view text) { return rich_text_plain(parse_rich_text(text)); }

}  // namespace vibra::render
