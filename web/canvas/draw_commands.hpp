// DrawCommands: a frame's drawing as a flat list of 2D-canvas operations, which web/canvas/replay.js hands to the browser's canvas.
#pragma once
#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace vibra::web {

/// One operation of the list; its arguments follow it in numbers().
/// Paths are in device pixels (the canvas's transform is the identity while
/// a path is built, as Cairo turns points into device space when they are
/// added); a stroke or a text run carries the user matrix it is drawn with.
enum class Op : int {
  kSave = 0,       ///< —
  kRestore,        ///< —
  kBeginPath,      ///< —
  kMoveTo,         ///< x y
  kLineTo,         ///< x y
  kClosePath,      ///< —
  kFill,           ///< r g b a evenodd
  kStroke,         ///< r g b a width join cap xx yx xy yy x0 y0 dash_count offset dashes...
  kClip,           ///< evenodd
  kPaint,          ///< r g b a: every pixel inside the clip
  kText,           ///< stroked(0|1) r g b a width join cap xx yx xy yy x0 y0 x y font text (string indices)
  kComposite,      ///< operator: 0 source-over, 1 copy, 2 destination-out (Cairo's OVER, SOURCE, CLEAR)
  kPushGroup,      ///< —: later operations go to a new transparent layer
  kPopGroupPaint,  ///< alpha: the layer painted onto the one below
  /// width height repeat(0|1) smooth(0|1) xx yx xy yy x0 y0 evenodd count first_string string_count, then
  /// `count` numbers: the path filled with a tile (a surface drawn by its own operations, whose strings are
  /// string_count from first_string), placed on the page by the matrix from the tile's pixels to the page's.
  kFillPattern,
};

/// What a stroke or a text run is drawn with: colour, pen and user matrix.
struct Pen {
  std::array<double, 4> rgba{0, 0, 0, 1};
  double width = 2;
  int join = 0, cap = 0;  ///< Cairo's numbering: miter, round, bevel; butt, round, square
  std::array<double, 6> matrix{1, 0, 0, 1, 0, 0};  ///< xx yx xy yy x0 y0
  std::vector<double> dashes;
  double dash_offset = 0;
};

class DrawCommands {
 public:
  void save() { op(Op::kSave); }
  void restore() { op(Op::kRestore); }
  void begin_path() { op(Op::kBeginPath); }
  void move_to(double x, double y) { op(Op::kMoveTo, {x, y}); }
  void line_to(double x, double y) { op(Op::kLineTo, {x, y}); }
  void close_path() { op(Op::kClosePath); }
  void fill(const std::array<double, 4>& rgba, bool even_odd);
  void stroke(const Pen& pen);
  void clip(bool even_odd) { op(Op::kClip, {double(even_odd)}); }
  void paint(const std::array<double, 4>& rgba);
  /// A run of text with its baseline's left end at (x, y) in user units.
  void text(bool stroked, const Pen& pen, double x, double y, const std::string& font, const std::string& text);
  void composite(int cairo_operator);
  void push_group() { op(Op::kPushGroup); }
  void pop_group_paint(double alpha) { op(Op::kPopGroupPaint, {alpha}); }
  /// The path filled with `tile` (width x height pixels), repeated or once,
  /// `to_page` taking the tile's pixels to the page's (xx yx xy yy x0 y0).
  void fill_pattern(const DrawCommands& tile, int width, int height, const std::array<double, 6>& to_page,
                    bool repeat, bool smooth, bool even_odd);

  const std::vector<double>& numbers() const { return numbers_; }
  const std::vector<std::string>& strings() const { return strings_; }
  /// The strings joined by '\n' (texts never hold one: a layout's lines are
  /// separate runs), as the page reads them in one call.
  std::string joined_strings() const;
  void clear();

 private:
  void op(Op o, std::initializer_list<double> args = {});
  void pen(const Pen& p, bool with_dashes);
  double string_index(const std::string& s);
  std::vector<double> numbers_;
  std::vector<std::string> strings_;
};

/// The operations as text, one per line ("moveTo 10 20"): what the tests
/// compare, and a readable dump of a frame.
std::string describe(const DrawCommands& commands);

}  // namespace vibra::web
