// Pango's markup subset parsed into styled runs: tags change the style on a stack, entities become their characters.
#include "web/shim/pango_markup.hpp"

#include <map>
#include <stdexcept>

namespace vibra::web::shim {

namespace {

/// DejaVu Sans's OS/2 table, which Pango 1.50 sets <sub> and <sup> by: the
/// script's size (ySubscriptYSize = ySuperscriptYSize = 1433 of 2048
/// units), <sub> lowered by ySubscriptYOffset (286) and <sup> raised by
/// ySuperscriptYOffset (983), in ems of the surrounding text.
constexpr double kScriptSize = 1433.0 / 2048, kSubscriptDrop = 286.0 / 2048, kSuperscriptRise = 983.0 / 2048;

/// Pango 1.50's styles: <small> one step of 1.2 smaller, <sub> and <sup> as the font's table says.
void apply_tag(const std::string& tag, RunStyle& s) {
  if (tag == "i") s.italic = true;
  else if (tag == "b") s.bold = true;
  else if (tag == "small" || tag == "span size=\"smaller\"") s.scale /= 1.2;
  else if (tag == "sub") s.rise -= kSubscriptDrop * s.scale, s.scale *= kScriptSize;
  else if (tag == "sup") s.rise += kSuperscriptRise * s.scale, s.scale *= kScriptSize;
  else if (tag != "span") throw std::invalid_argument("markup tag <" + tag + "> is not drawn in the browser");
}

/// The character an entity stands for (without its & and ;), in UTF-8.
std::string entity(const std::string& name) {
  static const std::map<std::string, std::string> kNamed = {
      {"amp", "&"}, {"lt", "<"}, {"gt", ">"}, {"quot", "\""}, {"apos", "'"}};
  if (auto it = kNamed.find(name); it != kNamed.end()) return it->second;
  if (name.size() < 2 || name[0] != '#') throw std::invalid_argument("markup entity &" + name + "; is unknown");
  const unsigned long c = name[1] == 'x' ? std::stoul(name.substr(2), nullptr, 16) : std::stoul(name.substr(1));
  std::string out;
  if (c < 0x80) out += char(c);
  else if (c < 0x800) out += char(0xC0 | c >> 6), out += char(0x80 | (c & 0x3F));
  else if (c < 0x10000) out += char(0xE0 | c >> 12), out += char(0x80 | (c >> 6 & 0x3F)), out += char(0x80 | (c & 0x3F));
  else out += char(0xF0 | c >> 18), out += char(0x80 | (c >> 12 & 0x3F)), out += char(0x80 | (c >> 6 & 0x3F)),
       out += char(0x80 | (c & 0x3F));
  return out;
}

}  // namespace

std::vector<MarkupRun> parse_markup(const std::string& markup) {
  std::vector<MarkupRun> runs;
  std::vector<RunStyle> styles{RunStyle{}};
  std::string text;
  auto flush = [&] {
    if (!text.empty()) runs.push_back({text, styles.back()});
    text.clear();
  };
  for (std::size_t i = 0; i < markup.size(); ++i) {
    const char c = markup[i];
    const std::size_t end = markup.find(c == '<' ? '>' : ';', i);
    if ((c != '<' && c != '&') || end == std::string::npos) {
      text += c;
      continue;
    }
    const std::string inside = markup.substr(i + 1, end - i - 1);
    i = end;
    if (c == '&') {
      text += entity(inside);
      continue;
    }
    flush();
    if (!inside.empty() && inside[0] == '/') {
      if (styles.size() > 1) styles.pop_back();
      continue;
    }
    styles.push_back(styles.back());
    apply_tag(inside, styles.back());
  }
  flush();
  return runs;
}

}  // namespace vibra::web::shim
