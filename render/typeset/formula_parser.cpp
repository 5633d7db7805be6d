// Parses the LaTeX subset vibra typesets ($...$ in titles, notes and equations) into elements.
#include "render/typeset/formula_parser.hpp"

#include <algorithm>
#include <optional>
#include <tuple>
#include <utility>

#include "core/error.hpp"
#include "core/input/parameters.hpp"
#include "core/input/quoted_value.hpp"

namespace vibra::render {

namespace {
constexpr std::string_view kSubset = "docs/drawing.md lists the LaTeX subset vibra typesets";

/// Decodes the UTF-8 code point at `at` into `c`; returns its length, 0 when invalid.
size_t decode_utf8(std::string_view s, size_t at, char32_t& c) {
  const unsigned char b = static_cast<unsigned char>(s[at]);
  size_t n = b < 0x80 ? 1 : (b >> 5) == 6 ? 2 : (b >> 4) == 14 ? 3 : (b >> 3) == 30 ? 4 : 0;
  if (n == 0 || at + n > s.size()) return 0;
  c = n == 1 ? b : n == 2 ? (b & 0x1f) : n == 3 ? (b & 0x0f) : (b & 0x07);
  for (size_t i = 1; i < n; ++i) {
    const unsigned char more = static_cast<unsigned char>(s[at + i]);
    if ((more >> 6) != 2) return 0;
    c = (c << 6) | (more & 0x3f);
  }
  // Overlong forms, surrogates and values beyond Unicode are not text.
  static constexpr char32_t kLeast[] = {0, 0, 0x80, 0x800, 0x10000};
  if (c < kLeast[n] || c > 0x10ffff || (c >= 0xd800 && c <= 0xdfff)) return 0;
  return n;
}

bool is_letter(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); }
bool is_digit(char c) { return c >= '0' && c <= '9'; }

MathNode glyph_node(std::string glyphs, Atom atom, MathFont font) {
  MathNode node;
  node.kind = MathNode::Kind::glyphs;
  node.glyphs = std::move(glyphs);
  node.atom = atom;
  node.font = font;
  return node;
}

MathNode space_node(double em) {
  MathNode node;
  node.kind = MathNode::Kind::space;
  node.space = em;
  return node;
}

/// Where a row ends: at the end of the input, at a closing brace, or at \right.
enum class RowEnd { input, brace, right };

class Parser {
 public:
  explicit Parser(std::string_view source) : src_(source) {}

  Formula parse() {
    if (src_.size() > kMaxFormulaLength)
      fail("it is too long (" + std::to_string(src_.size()) + " characters; at most " +
           std::to_string(kMaxFormulaLength) + "): shorten it or split it");
    Formula formula;
    formula.source = std::string(src_);
    do {
      newline_ = false;
      formula.lines.push_back(parse_row(RowEnd::input));
    } while (newline_);
    return formula;
  }

 private:
  [[noreturn]] void fail(const std::string& message) const {
    throw UsageError("formula '" + quoted_value(src_, 48) + "': " + message);
  }

  bool at_end() const { return pos_ >= src_.size(); }
  char peek() const { return at_end() ? '\0' : src_[pos_]; }
  void skip_spaces() {
    while (!at_end() && (src_[pos_] == ' ' || src_[pos_] == '\t' || src_[pos_] == '\n' || src_[pos_] == '\r')) ++pos_;
  }

  /// One level deeper (a group, a fraction's part, a script...), checked.
  struct Nest {
    explicit Nest(Parser& p) : p(p) {
      if (++p.depth_ > kMaxFormulaDepth)
        p.fail("it nests deeper than " + std::to_string(kMaxFormulaDepth) +
               " levels (braces, fractions, scripts, roots): flatten it");
    }
    ~Nest() { --p.depth_; }
    Parser& p;
  };

  /// The command after a backslash: a run of letters, or one other character.
  std::string read_command() {
    ++pos_;  // the backslash
    if (at_end()) fail("it ends with a lone \\: remove it, or write a command such as \\alpha");
    const size_t start = pos_;
    if (is_letter(src_[pos_])) {
      while (!at_end() && is_letter(src_[pos_])) ++pos_;
    } else {
      char32_t c;
      const size_t n = decode_utf8(src_, pos_, c);
      if (n == 0) fail_not_utf8();
      pos_ += n;
    }
    return std::string(src_.substr(start, pos_ - start));
  }

  [[noreturn]] void fail_not_utf8() const {
    fail("byte " + std::to_string(pos_ + 1) + " is not UTF-8 text: save the text as UTF-8");
  }

  /// One character as a glyph node, letters italic, the rest as math_character says.
  MathNode character() {
    char32_t c;
    const size_t n = decode_utf8(src_, pos_, c);
    if (n == 0) fail_not_utf8();
    if (c < 0x20 || c == 0x7f) fail("it holds a control character (" + quoted_value(src_.substr(pos_, 1)) + "): remove it");
    std::string text(src_.substr(pos_, n));
    pos_ += n;
    MathSymbol symbol = math_character(c);
    MathFont font = symbol.font;
    if (font == MathFont::italic && override_font_) font = *override_font_;
    return glyph_node(symbol.glyphs.empty() ? text : std::string(symbol.glyphs), symbol.atom, font);
  }

  /// Digits and decimal points as one upright number: 0.05, 2.
  MathNode number() {
    const size_t start = pos_;
    while (!at_end() && (is_digit(src_[pos_]) || (src_[pos_] == '.' && pos_ + 1 < src_.size() && is_digit(src_[pos_ + 1]))))
      ++pos_;
    return glyph_node(std::string(src_.substr(start, pos_ - start)), Atom::ord,
                      override_font_ == MathFont::bold ? MathFont::bold : MathFont::upright);
  }

  MathNode parse_row(RowEnd end) {
    MathNode row;
    row.kind = MathNode::Kind::group;
    while (true) {
      skip_spaces();
      if (at_end()) {
        if (end == RowEnd::brace) fail("a { is never closed: add the matching }");
        if (end == RowEnd::right) fail("a \\left has no matching \\right: add \\right) (or \\right. for none)");
        return row;
      }
      const char c = peek();
      if (c == '}') {
        if (end == RowEnd::brace) return row;
        fail("a } closes nothing: remove it, or open it with {");
      }
      if (c == '^' || c == '_') {
        ++pos_;
        attach_script(row, c == '^');
        continue;
      }
      if (c == '\'') {
        attach_primes(row);
        continue;
      }
      if (c == '\\') {
        const size_t at = pos_;
        const std::string name = read_command();
        if (name == "\\") {
          if (end != RowEnd::input || depth_ > 0)
            fail("\\\\ breaks lines only at the top level, not inside braces or \\left...\\right: move it out");
          newline_ = true;
          return row;
        }
        if (name == "right") {
          if (end == RowEnd::right) return row;
          fail("a \\right has no \\left before it: add \\left( (or \\left. for none)");
        }
        pos_ = at;
        row.parts.push_back(parse_atom());
        continue;
      }
      row.parts.push_back(parse_atom());
    }
  }

  /// One atom: a character, a number, a braced group or a command with its arguments.
  MathNode parse_atom() {
    const char c = peek();
    switch (c) {
      case '{': {
        ++pos_;
        Nest nest(*this);
        MathNode group = parse_row(RowEnd::brace);
        ++pos_;  // the }
        return group;
      }
      case '\\': return parse_command(read_command());
      case '$': fail("a $ inside a formula: formulas are math already; write \\$ for a dollar sign");
      case '%': fail("% starts a comment in LaTeX, which formulas do not have: write \\% for a percent sign");
      case '&': fail("& (alignment) is not supported: write one equation per line, separated by \\\\");
      case '#': fail("# is not allowed in a formula: write \\# for the sign");
      case '~': ++pos_; return space_node(1.0 / 3);
      case '}': fail("an argument is missing before }: write e.g. \\frac{a}{b} or x^{2}");
      case '^':
      case '_': fail(std::string("a ") + c + " follows " + (c == '^' ? "^" : "_") + " or an argument is missing: write x^{2} or x_{n}");
      case '\'': fail("a prime needs something before it: write u'");
      default: break;
    }
    if (is_digit(c)) return number();
    return character();
  }

  /// A command's argument, or a script's: a braced group, a command, or one character.
  MathNode argument(const std::string& what, const std::string& example) {
    skip_spaces();
    if (at_end() || peek() == '}' || peek() == '^' || peek() == '_' || peek() == '\'')
      fail(what + " needs an argument: write " + example);
    if (peek() == '{') return parse_atom();  // nests one level itself
    Nest nest(*this);
    if (peek() == '\\') {
      const size_t at = pos_;
      const std::string name = read_command();
      if (name == "right" || name == "\\") fail(what + " needs an argument: write " + example);
      pos_ = at;
      return parse_atom();
    }
    if (is_digit(peek())) {  // one digit, as TeX takes x^23 as x^2 then 3
      ++pos_;
      return glyph_node(std::string(1, src_[pos_ - 1]), Atom::ord, MathFont::upright);
    }
    return parse_atom();
  }

  void attach_script(MathNode& row, bool superscript) {
    const char* mark = superscript ? "^" : "_";
    MathNode script = argument(mark, superscript ? "x^2 or x^{n+1}" : "x_1 or x_{n+1}");
    if (row.parts.empty() || row.parts.back().kind != MathNode::Kind::scripts) {
      MathNode scripts;
      scripts.kind = MathNode::Kind::scripts;
      scripts.parts.resize(3);
      if (!row.parts.empty()) {
        scripts.parts[0] = std::move(row.parts.back());
        row.parts.pop_back();
      }
      row.parts.push_back(std::move(scripts));
    }
    MathNode& scripts = row.parts.back();
    bool& has = superscript ? scripts.has_sup : scripts.has_sub;
    if (has)
      fail(std::string("double ") + (superscript ? "superscript" : "subscript") + ": group them, e.g. x" + mark +
           "{ab} or {x" + mark + "a}" + mark + "b");
    has = true;
    scripts.parts[superscript ? 1 : 2] = std::move(script);
  }

  void attach_primes(MathNode& row) {
    int count = 0;
    while (peek() == '\'') ++pos_, ++count;
    static constexpr const char* kPrimes[] = {"′", "″", "‴", "⁗"};
    std::string glyphs;
    for (int left = count; left > 0; left -= 4) glyphs += kPrimes[std::min(left, 4) - 1];
    MathNode prime = glyph_node(glyphs, Atom::ord, MathFont::upright);
    if (row.parts.empty()) {
      row.parts.push_back(std::move(prime));
      return;
    }
    MathNode& last = row.parts.back();
    if (last.kind == MathNode::Kind::scripts) {
      if (last.has_sup) fail("a prime after a superscript: write u'^2, or {u^2}'");
      last.has_sup = true;
      last.parts[1] = std::move(prime);
      return;
    }
    MathNode base;
    base.kind = MathNode::Kind::group;
    base.atom = last.atom == Atom::op ? Atom::op : Atom::ord;
    base.parts.push_back(std::move(last));
    base.parts.push_back(std::move(prime));
    last = std::move(base);
  }

  /// The delimiter after \left or \right.
  std::string delimiter(const char* command) {
    skip_spaces();
    const char c = peek();
    if (c == '(' || c == ')' || c == '[' || c == ']' || c == '|' || c == '.') {
      ++pos_;
      return std::string(1, c);
    }
    if (c == '\\') {
      const size_t at = pos_;
      const std::string name = read_command();
      if (name == "|") return "‖";
      if (name == "langle") return "⟨";
      if (name == "rangle") return "⟩";
      pos_ = at;
    }
    fail(std::string("\\") + command + " needs a delimiter after it: one of ( ) [ ] | \\| \\langle \\rangle, or . for none");
  }

  /// \text{...}: the words as typed, spaces kept.
  MathNode text_argument(const std::string& command) {
    skip_spaces();
    if (peek() != '{') fail("\\" + command + " needs its text in braces: write \\" + command + "{ at rest}");
    ++pos_;
    Nest nest(*this);
    std::string text;
    int open = 1;
    while (true) {
      if (at_end()) fail("the { of \\" + command + " is never closed: add the matching }");
      const char c = src_[pos_];
      if (c == '{') {
        ++open, ++pos_;
        continue;
      }
      if (c == '}') {
        ++pos_;
        if (--open == 0) break;
        continue;
      }
      if (c == '\\') {
        const std::string name = read_command();
        if (name.size() == 1 && std::string_view("$%&#_{} ").find(name[0]) != std::string_view::npos) {
          text += name;
          continue;
        }
        fail("\\" + command + "{...} holds plain text, not \\" + name + ": end the text before it, e.g. \\text{at } \\" + name);
      }
      char32_t code;
      const size_t n = decode_utf8(src_, pos_, code);
      if (n == 0) fail_not_utf8();
      if (code < 0x20 || code == 0x7f) fail("it holds a control character: remove it");
      text.append(src_.substr(pos_, n));
      pos_ += n;
    }
    return glyph_node(text, Atom::ord, MathFont::text);
  }

  MathNode with_font(MathFont font, const std::string& command) {
    const std::optional<MathFont> outer = override_font_;
    override_font_ = font;
    MathNode group = argument("\\" + command, "\\" + command + "{d}");
    override_font_ = outer;
    if (group.kind != MathNode::Kind::group) {
      MathNode row;
      row.parts.push_back(std::move(group));
      group = std::move(row);
    }
    return group;
  }

  /// \frac, \sqrt and \left...\right: commands with arguments or a body.
  std::optional<MathNode> parse_structure(const std::string& name) {
    MathNode node;
    if (name == "frac" || name == "dfrac" || name == "tfrac") {
      node.kind = MathNode::Kind::fraction;
      node.atom = Atom::inner;
      node.parts.push_back(argument("\\" + name, "\\frac{a}{b}"));
      node.parts.push_back(argument("\\" + name + "{...}", "\\frac{a}{b} (two arguments)"));
      return node;
    }
    if (name == "sqrt") {
      skip_spaces();
      if (peek() == '[') fail("\\sqrt[n] (an n-th root) is not supported: write x^{1/n}");
      node.kind = MathNode::Kind::radical;
      node.parts.push_back(argument("\\sqrt", "\\sqrt{x}"));
      return node;
    }
    if (name != "left") return std::nullopt;
    node.kind = MathNode::Kind::delimited;
    node.atom = Atom::inner;
    node.glyphs = delimiter("left");
    {
      Nest nest(*this);
      node.parts.push_back(parse_row(RowEnd::right));
    }
    node.close = delimiter("right");
    return node;
  }

  /// Text, font and accent commands: one argument, set in a style.
  std::optional<MathNode> parse_styled(const std::string& name) {
    if (name == "text") return text_argument(name);
    static const std::pair<const char*, MathFont> kFonts[] = {
        {"mathrm", MathFont::upright}, {"mathbf", MathFont::bold}, {"mathit", MathFont::italic}};
    for (const auto& [command, font] : kFonts)
      if (name == command) return with_font(font, name);
    if (name == "operatorname") {
      MathNode node = with_font(MathFont::upright, name);
      node.atom = Atom::op;
      return node;
    }
    static const std::pair<const char*, const char*> kAccents[] = {
        {"dot", "˙"}, {"ddot", "¨"}, {"hat", "ˆ"}, {"tilde", "˜"}, {"vec", "→"}, {"bar", ""}};
    for (const auto& [accent, glyph] : kAccents) {
      if (name != accent) continue;
      MathNode node;
      node.kind = MathNode::Kind::accent;
      node.glyphs = glyph;
      node.parts.push_back(argument("\\" + name, "\\" + name + "{u}"));
      return node;
    }
    return std::nullopt;
  }

  /// Spaces, escaped characters, delimiters and symbols: no argument.
  std::optional<MathNode> parse_glyph_command(const std::string& name) {
    static const std::pair<const char*, double> kSpaces[] = {  // in em
        {"quad", 1},        {"qquad", 2},         {",", 3.0 / 18}, {":", 4.0 / 18},
        {">", 4.0 / 18},    {";", 5.0 / 18},      {"!", -3.0 / 18}, {" ", 1.0 / 3}};
    for (const auto& [command, em] : kSpaces)
      if (name == command) return space_node(em);
    static const std::tuple<const char*, const char*, Atom> kGlyphs[] = {
        {"|", "‖", Atom::ord},     {"{", "{", Atom::open},       {"}", "}", Atom::close},
        {"langle", "⟨", Atom::open}, {"rangle", "⟩", Atom::close}};
    for (const auto& [command, glyph, atom] : kGlyphs)
      if (name == command) return glyph_node(glyph, atom, MathFont::upright);
    if (name.size() == 1 && std::string_view("$%&#_").find(name[0]) != std::string_view::npos)
      return glyph_node(name, Atom::ord, MathFont::upright);
    const std::optional<MathSymbol> symbol = math_symbol(name);
    if (!symbol) return std::nullopt;
    MathFont font = symbol->font;
    if (font == MathFont::italic && override_font_) font = *override_font_;
    return glyph_node(std::string(symbol->glyphs), symbol->atom, font);
  }

  MathNode parse_command(const std::string& name) {
    if (std::optional<MathNode> node = parse_structure(name)) return std::move(*node);
    if (std::optional<MathNode> node = parse_styled(name)) return std::move(*node);
    if (std::optional<MathNode> node = parse_glyph_command(name)) return std::move(*node);
    const std::string near = is_letter(name[0]) ? closest_match(name, math_command_names()) : "";
    fail("unknown command \\" + quoted_value(name, 24) + (near.empty() ? "" : " (did you mean \\" + near + "?)") + ": " +
         std::string(kSubset));
  }

  std::string_view src_;
  size_t pos_ = 0;
  int depth_ = 0;
  bool newline_ = false;
  std::optional<MathFont> override_font_;
};
}  // namespace

Formula parse_formula(std::string_view source) { return Parser(source).parse(); }

std::vector<RichRun> parse_rich_text(std::string_view text) {
  if (text.size() > kMaxFormulaLength)
    throw UsageError("text '" + quoted_value(text, 48) + "' is too long (" + std::to_string(text.size()) +
                     " characters; at most " + std::to_string(kMaxFormulaLength) + "): shorten it");
  std::vector<RichRun> runs;
  std::string plain;
  for (size_t i = 0; i < text.size();) {
    char32_t c;
    const size_t n = decode_utf8(text, i, c);
    if (n == 0)
      throw UsageError("text '" + quoted_value(text, 48) + "': byte " + std::to_string(i + 1) +
                       " is not UTF-8 text: save the text as UTF-8");
    if (c < 0x20 || c == 0x7f)
      throw UsageError("text '" + quoted_value(text, 48) + "' holds a control character (a line break?): write it on one line");
    if (c == '\\' && i + 1 < text.size() && text[i + 1] == '$') {
      plain += '$', i += 2;
      continue;
    }
    if (c != '$') {
      plain.append(text.substr(i, n)), i += n;
      continue;
    }
    // $ ... $: the formula up to the next unescaped $.
    size_t end = i + 1;
    while (end < text.size() && !(text[end] == '$' && text[end - 1] != '\\')) ++end;
    if (end >= text.size())
      throw UsageError("text '" + quoted_value(text, 48) +
                       "': a $ opens math that is never closed: add the closing $, or write \\$ for a dollar sign");
    const std::string_view source = text.substr(i + 1, end - i - 1);
    if (!plain.empty()) runs.push_back({false, std::move(plain), {}}), plain.clear();
    if (source.find_first_not_of(" ") != std::string_view::npos)
      runs.push_back({true, std::string(source), parse_formula(source)});
    i = end + 1;
  }
  if (!plain.empty()) runs.push_back({false, std::move(plain), {}});
  return runs;
}

}  // namespace vibra::render
