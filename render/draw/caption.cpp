// A run's caption (facts joined by " · ") broken onto lines and shrunk to fit a width.
#include "render/draw/caption.hpp"

#include <string_view>

namespace vibra::render {

namespace {
std::vector<std::string> facts_of(const std::string& markup) {
  std::vector<std::string> facts;
  const std::string_view separator = kCaptionSeparator;
  size_t from = 0;
  for (size_t at; (at = markup.find(separator, from)) != std::string::npos; from = at + separator.size())
    facts.push_back(markup.substr(from, at - from));
  facts.push_back(markup.substr(from));
  return facts;
}

/// Facts packed greedily onto lines no wider than `width`; a fact wider
/// than `width` takes a line of its own.
std::vector<std::string> packed(Canvas& canvas, const std::vector<std::string>& facts, double width,
                                const TextStyle& style) {
  std::vector<std::string> lines;
  for (const std::string& fact : facts) {
    if (!lines.empty()) {
      const std::string longer = lines.back() + kCaptionSeparator + fact;
      if (text_size(canvas, longer, style).x() <= width) {
        lines.back() = longer;
        continue;
      }
    }
    lines.push_back(fact);
  }
  return lines;
}

bool fits(Canvas& canvas, const std::vector<std::string>& lines, double width, const TextStyle& style) {
  for (const std::string& line : lines)
    if (text_size(canvas, line, style).x() > width) return false;
  return true;
}
}  // namespace

Caption fit_caption(Canvas& canvas, const std::string& markup, double width, TextStyle style, int max_lines) {
  const std::vector<std::string> facts = facts_of(markup);
  const double full = style.size;
  std::vector<std::string> lines;
  for (double shrink : {1.0, 0.9, 0.8}) {
    style.size = full * shrink;
    lines = packed(canvas, facts, width, style);
    if (int(lines.size()) <= max_lines && fits(canvas, lines, width, style)) break;
  }
  // Still too long at 80%: the last line takes the rest of the facts and ends in "…".
  if (int(lines.size()) > max_lines) {
    std::string rest = lines[size_t(max_lines) - 1];
    for (size_t i = size_t(max_lines); i < lines.size(); ++i) rest += kCaptionSeparator + lines[i];
    lines.resize(size_t(max_lines));
    lines.back() = rest;
  }
  style.max_width = width;
  return {lines, style, text_size(canvas, "Δ<i>t</i>", style).y()};
}

void draw_caption(Canvas& canvas, const Point& bottom_left, const Caption& caption) {
  for (size_t i = 0; i < caption.lines.size(); ++i) {
    const double below = caption.line_height * double(caption.lines.size() - 1 - i);
    draw_text(canvas, {bottom_left.x(), bottom_left.y() - below}, caption.lines[i], caption.style,
              Anchor::bottom_left);
  }
}

}  // namespace vibra::render
