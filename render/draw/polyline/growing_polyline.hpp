// A curve against time known in full before it is shown, drawn up to an instant: whole on a still, in strips on a video's layer.
#pragma once
#include <optional>
#include <vector>

#include "render/draw/canvas.hpp"
#include "render/draw/elements/shapes.hpp"

namespace vibra::render {

/// A polyline known in full before any of it is shown (a whole run's curve,
/// in pixels, x never decreasing), shown up to an x (an instant) at a time:
/// whole on a still, and on an animation's layer in pieces that come out as
/// the whole stroke would, so that a frame is the still at its time however
/// many samples one frame spans (none, one or thousands).
///
/// Shown up to x, the curve holds its points left of x or at it, and then
/// runs on to where the curve is at that instant (the `now` point the caller
/// gives, from the solution at that time), never to a point after it.
///
/// A piece is stroked from far enough back that every segment touching its
/// strip is in the path, with the dash phase the whole path has there, and
/// clipped to the strip; the caller first restores the strip's background.
class GrowingPolyline {
 public:
  GrowingPolyline() = default;
  explicit GrowingPolyline(std::vector<Point> points);

  /// How far a stroke of `width` pixels can reach from its path: half the
  /// width, a miter join at Cairo's default limit (10), anti-aliasing.
  static double reach(double width) { return 6 * width + 3; }

  /// Strokes the curve up to `until_x` as one path.
  void draw_until(Canvas&, double until_x, const std::optional<Point>& now, const Stroke&) const;
  /// The same, only where x >= `from_x` (a whole pixel), as the whole curve
  /// would be drawn there.
  void draw_piece_until(Canvas&, double from_x, double until_x, const std::optional<Point>& now, const Stroke&) const;
  /// The x of the last point at or left of `until_x`, if any: left of it
  /// (less the stroke's reach) the curve shown up to `until_x` is final.
  std::optional<double> last_x(double until_x) const;
  /// Whether every point is at or left of `until_x`: the curve has ended
  /// there (a run that left the view), so nothing of it is still to come.
  bool complete_until(double until_x) const { return shown(until_x) == int(points_.size()); }
  const std::vector<Point>& points() const { return points_; }

 private:
  /// How many points lie at or left of `until_x`.
  int shown(double until_x) const;
  void draw_range(Canvas&, int first, int end, const std::optional<Point>& now, const Stroke&) const;

  std::vector<Point> points_;
  std::vector<double> length_;  ///< path length from the first point to each point, for the dash phase
};

}  // namespace vibra::render
