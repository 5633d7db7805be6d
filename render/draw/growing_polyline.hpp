#pragma once
#include <optional>
#include <vector>

#include "render/draw/canvas.hpp"
#include "render/draw/shapes.hpp"

namespace vibra::render {

/// A polyline known in full before any of it is shown (a whole run's curve,
/// in pixels), shown up to a pixel column at a time: whole on a still, and on
/// an animation's layer in pieces that come out as the whole stroke would, so
/// that a frame is the still at its time however many samples one frame
/// spans (none, one or thousands).
///
/// A piece is stroked from far enough back that every segment touching its
/// strip is in the path, with the dash phase the whole path has there, and
/// clipped to the strip; the caller first restores the strip's background.
class GrowingPolyline {
 public:
  GrowingPolyline() = default;
  /// `points` in drawing order; `ends[c]`: how many of them belong to
  /// columns 0..c (non-decreasing).
  GrowingPolyline(std::vector<Point> points, std::vector<int> ends);

  /// How far a stroke of `width` pixels can reach from its path: half the
  /// width, a miter join at Cairo's default limit (10), anti-aliasing.
  static double reach(double width) { return 6 * width + 3; }

  /// Strokes every point through `last_column` as one path.
  void draw_through(Canvas&, int last_column, const Stroke&) const;
  /// Strokes the points through `last_column`, only where x >= `from_x`
  /// (a whole pixel), as the whole path would be stroked there.
  void draw_piece(Canvas&, double from_x, int last_column, const Stroke&) const;
  /// The x of the last point through `last_column`, if any.
  std::optional<double> last_x(int last_column) const;
  /// Whether every point is through `last_column`: the curve has ended there
  /// (a run that left the view), so nothing of it is still to come.
  bool complete_through(int last_column) const { return end_of(last_column) == int(points_.size()); }

 private:
  int end_of(int last_column) const;
  void stroke_range(Canvas&, int first, int end, const Stroke&) const;

  std::vector<Point> points_;
  std::vector<double> length_;  ///< path length from the first point to each point, for the dash phase
  std::vector<int> ends_;
};

}  // namespace vibra::render
