#pragma once
#include <cstddef>
#include <vector>

#include "render/canvas.hpp"
#include "render/color.hpp"

namespace vibra::render {

/// The path a body leaves behind, stamped with time and thinned as it streams
/// in: a point is kept only `spacing` world units from the last one kept
/// (finer than a pixel at the sizes drawn), and when more than `budget` are
/// kept the spacing doubles and every other point goes. So a run of a million
/// steps holds no more points than one of a thousand, and drawing the part of
/// the path within a time window costs what that part's length says, never
/// what the step count says.
class Trail {
 public:
  explicit Trail(double spacing, size_t budget = size_t(1) << 16);

  /// Points must come in time order.
  void add(double t, const Point& p);
  /// The path from `t - fade` to `t` as a polyline whose opacity falls from
  /// 1 at t to 0 at `t - fade`; it ends at the latest point before t.
  void draw(Canvas&, const WorldView&, double t, double fade, const Color&, double width) const;

  struct Stamped {
    double t;
    Point p;
  };
  const std::vector<Stamped>& points() const { return points_; }
  /// The kept points with time in [from, to].
  std::vector<Point> between(double from, double to) const;
  double spacing() const { return spacing_; }

 private:
  double spacing_;
  size_t budget_;
  std::vector<Stamped> points_;
};

}  // namespace vibra::render
