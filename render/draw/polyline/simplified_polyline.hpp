// Polyline simplification in one pass: the points a curve needs to stay within a tolerance of every sample.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "render/draw/canvas.hpp"

namespace vibra::render {

/// The points a polyline within `tolerance` of every one of the `n` points
/// `point_of(i)` needs, as indices (first and last always kept), in one pass:
/// from the last kept point (the anchor), each later point narrows the wedge
/// of directions whose ray passes within `tolerance` of it; the point that
/// leaves the wedge, or turns back towards the anchor, ends the segment at
/// the point before it. A smooth curve drawn in pixels needs a few dozen
/// segments per turn, however finely it was sampled.
template <class PointOf>
std::vector<size_t> simplified_polyline(size_t n, PointOf point_of, double tolerance) {
  std::vector<size_t> out;
  if (n <= 2) {
    for (size_t i = 0; i < n; ++i) out.push_back(i);
    return out;
  }
  out.push_back(0);
  size_t anchor = 0, last = 0;
  Point origin = point_of(0), direction = Point::Zero();
  bool aimed = false;
  double lo = 0, hi = 0, reach = 0;
  auto narrow = [&](size_t i) {  // false: point i does not fit the current segment
    const Point d = point_of(i) - origin;
    const double length = d.norm();
    if (length <= tolerance) return true;  // near the anchor: any segment from it passes near enough
    const double half = std::asin(std::min(1.0, tolerance / length));
    if (!aimed) {
      direction = d / length, lo = -half, hi = half, reach = length, aimed = true;
      return true;
    }
    const double angle = std::atan2(direction.x() * d.y() - direction.y() * d.x(), direction.dot(d));
    if (angle < lo || angle > hi || length < reach - tolerance) return false;
    lo = std::max(lo, angle - half), hi = std::min(hi, angle + half), reach = std::max(reach, length);
    return true;
  };
  for (size_t i = 1; i < n; ++i) {
    if (!narrow(i)) {
      out.push_back(last);
      anchor = last, origin = point_of(anchor), aimed = false;
      narrow(i);  // from the new anchor, the next point always fits
    }
    last = i;
  }
  out.push_back(n - 1);
  return out;
}

}  // namespace vibra::render
