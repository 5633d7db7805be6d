// DrawCommands: appending a frame's 2D-canvas operations to one list of numbers and one of strings.
#include "web/canvas/draw_commands.hpp"

#include <sstream>

namespace vibra::web {

void DrawCommands::op(Op o, std::initializer_list<double> args) {
  numbers_.push_back(static_cast<double>(o));
  numbers_.insert(numbers_.end(), args);
}

void DrawCommands::pen(const Pen& p, bool with_dashes) {
  numbers_.insert(numbers_.end(), p.rgba.begin(), p.rgba.end());
  numbers_.insert(numbers_.end(), {p.width, double(p.join), double(p.cap)});
  numbers_.insert(numbers_.end(), p.matrix.begin(), p.matrix.end());
  if (!with_dashes) return;
  numbers_.insert(numbers_.end(), {double(p.dashes.size()), p.dash_offset});
  numbers_.insert(numbers_.end(), p.dashes.begin(), p.dashes.end());
}

double DrawCommands::string_index(const std::string& s) {
  // The font of every run of a frame is one of a few: look back a little.
  for (std::size_t i = strings_.size(), seen = 0; i-- > 0 && seen < 8; ++seen)
    if (strings_[i] == s) return double(i);
  strings_.push_back(s);
  return double(strings_.size() - 1);
}

void DrawCommands::fill(const std::array<double, 4>& rgba, bool even_odd) {
  op(Op::kFill, {rgba[0], rgba[1], rgba[2], rgba[3], double(even_odd)});
}

void DrawCommands::stroke(const Pen& p) {
  op(Op::kStroke);
  pen(p, true);
}

void DrawCommands::paint(const std::array<double, 4>& rgba) { op(Op::kPaint, {rgba[0], rgba[1], rgba[2], rgba[3]}); }

void DrawCommands::text(bool stroked, const Pen& p, double x, double y, const std::string& font,
                        const std::string& text) {
  op(Op::kText, {double(stroked)});
  // The text may be "\n"-free only: joined_strings() splits on it.
  std::string one_line = text;
  for (char& c : one_line)
    if (c == '\n') c = ' ';
  pen(p, false);
  numbers_.insert(numbers_.end(), {x, y, string_index(font), string_index(one_line)});
}

void DrawCommands::composite(int cairo_operator) {
  // Cairo's CLEAR is 0, SOURCE 1, OVER 2 (web/shim/cairo.h).
  const double canvas_operator = cairo_operator == 0 ? 2 : cairo_operator == 1 ? 1 : 0;
  op(Op::kComposite, {canvas_operator});
}

void DrawCommands::fill_pattern(const DrawCommands& tile, int width, int height, const std::array<double, 6>& to_page,
                                bool repeat, bool smooth, bool even_odd) {
  op(Op::kFillPattern, {double(width), double(height), double(repeat), double(smooth)});
  numbers_.insert(numbers_.end(), to_page.begin(), to_page.end());
  numbers_.insert(numbers_.end(), {double(even_odd), double(tile.numbers_.size()), double(strings_.size()),
                                   double(tile.strings_.size())});
  numbers_.insert(numbers_.end(), tile.numbers_.begin(), tile.numbers_.end());
  strings_.insert(strings_.end(), tile.strings_.begin(), tile.strings_.end());
}

std::string DrawCommands::joined_strings() const {
  std::string joined;
  for (std::size_t i = 0; i < strings_.size(); ++i) joined += (i ? "\n" : "") + strings_[i];
  return joined;
}

void DrawCommands::clear() {
  numbers_.clear();
  strings_.clear();
}

namespace {

/// Each operation's name and how many numbers follow it (-1: a stroke, whose
/// dashes make its length vary).
struct OpShape {
  const char* name;
  int arguments;
};
constexpr OpShape kOpShapes[] = {
    {"save", 0},   {"restore", 0},        {"beginPath", 0}, {"moveTo", 2}, {"lineTo", 2},
    {"closePath", 0}, {"fill", 5},        {"stroke", -1},   {"clip", 1},   {"paint", 4},
    {"text", 18},  {"composite", 1},      {"pushGroup", 0}, {"popGroupPaint", 1}, {"fillPattern", 14},
};
constexpr int kStrokeFixed = 13;    // rgba, width, join, cap, matrix; then the dashes
constexpr int kPatternCount = 11;   // where a pattern's count of tile numbers sits among its arguments
constexpr int kMostTileDepth = 8;   // tiles drawn with tiles: deeper is not described

/// The operations of n[begin, end), each line after `indent`; a tile's
/// operations follow its fillPattern line, indented.
bool describe_into(std::ostringstream& out, const std::vector<double>& n, std::size_t begin, std::size_t end,
                   const std::string& indent) {
  constexpr int kOps = sizeof kOpShapes / sizeof kOpShapes[0];
  for (std::size_t i = begin; i < end;) {
    const int op = int(n[i++]);
    if (op < 0 || op >= kOps || indent.size() > 2 * kMostTileDepth) return out << indent << "unknown operation\n", false;
    const OpShape& shape = kOpShapes[op];
    int count = shape.arguments;
    if (count < 0 && i + kStrokeFixed < end) count = kStrokeFixed + 2 + int(n[i + kStrokeFixed]);
    out << indent << shape.name;
    const std::size_t tile = op == int(Op::kFillPattern) && i + kPatternCount < end ? std::size_t(n[i + kPatternCount]) : 0;
    for (int k = 0; k < count && i < end; ++k) out << ' ' << n[i++];
    out << '\n';
    if (tile > end - i || !describe_into(out, n, i, i + tile, indent + "  ")) return false;
    i += tile;
  }
  return true;
}

}  // namespace

std::string describe(const DrawCommands& commands) {
  std::ostringstream out;
  describe_into(out, commands.numbers(), 0, commands.numbers().size(), "");
  return out.str();
}

}  // namespace vibra::web
