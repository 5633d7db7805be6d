// Clips paths that reach far outside the picture before Cairo sees them (its 24.8 fixed point would wrap).
#include "render/draw/reach_clip.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace vibra::render {

namespace {
/// Clips the segment a-b to the box (Liang-Barsky); false: nothing of it is inside.
bool clip_segment(Point& a, Point& b) {
  if (!std::isfinite(a.x()) || !std::isfinite(a.y()) || !std::isfinite(b.x()) || !std::isfinite(b.y())) return false;
  const Point d = b - a;
  double t0 = 0, t1 = 1;
  auto edge = [&](double p, double q) {  // keeps t where p t <= q
    if (p == 0) return q >= 0;
    const double r = q / p;
    if (p < 0) {
      if (r > t1) return false;
      if (r > t0) t0 = r;
    } else {
      if (r < t0) return false;
      if (r < t1) t1 = r;
    }
    return true;
  };
  if (!edge(-d.x(), a.x() + kReach) || !edge(d.x(), kReach - a.x()) || !edge(-d.y(), a.y() + kReach) ||
      !edge(d.y(), kReach - a.y()))
    return false;
  const Point start = a + t0 * d, end = a + t1 * d;
  a = start, b = end;
  return true;
}

/// The part of `in` on the inside of one edge of the box: `axis` 0 (x) or 1
/// (y), `sign` +1 (<= kReach) or -1 (>= -kReach).
std::vector<Point> clip_edge(const std::vector<Point>& in, int axis, double sign) {
  std::vector<Point> out;
  auto inside = [&](const Point& p) { return sign * p[axis] <= kReach; };
  for (size_t i = 0; i < in.size(); ++i) {
    const Point& p = in[i];
    const Point& q = in[(i + 1) % in.size()];
    if (inside(p)) out.push_back(p);
    if (inside(p) != inside(q)) {
      const double t = (sign * kReach - p[axis]) / (q[axis] - p[axis]);
      out.push_back(p + t * (q - p));
    }
  }
  return out;
}
}  // namespace

bool within_reach(const Point& p) { return std::abs(p.x()) <= kReach && std::abs(p.y()) <= kReach; }

void add_polyline(cairo_t* cr, std::span<const Point> points) {
  if (std::all_of(points.begin(), points.end(), within_reach)) {
    for (size_t i = 0; i < points.size(); ++i)
      (i == 0 ? cairo_move_to : cairo_line_to)(cr, points[i].x(), points[i].y());
    return;
  }
  Point pen = Point::Zero();
  bool down = false;  // the path's current point is pen
  for (size_t i = 1; i < points.size(); ++i) {
    Point a = points[i - 1], b = points[i];
    if (!clip_segment(a, b)) {
      down = false;
      continue;
    }
    if (!down || a != pen) cairo_move_to(cr, a.x(), a.y());
    cairo_line_to(cr, b.x(), b.y());
    pen = b, down = true;
  }
}

void add_polygon(cairo_t* cr, std::span<const Point> points) {
  const auto emit = [cr](std::span<const Point> polygon) {
    if (polygon.size() < 3) return;
    cairo_move_to(cr, polygon[0].x(), polygon[0].y());
    for (size_t i = 1; i < polygon.size(); ++i) cairo_line_to(cr, polygon[i].x(), polygon[i].y());
    cairo_close_path(cr);
  };
  // The usual case, every frame's arrowheads and boxes: as given, nothing copied.
  if (std::all_of(points.begin(), points.end(), within_reach)) return emit(points);
  std::vector<Point> polygon;
  for (const Point& p : points)
    if (std::isfinite(p.x()) && std::isfinite(p.y())) polygon.push_back(p);
  for (int axis : {0, 1})
    for (double sign : {1.0, -1.0}) polygon = clip_edge(polygon, axis, sign);
  emit(polygon);
}

void add_arc(cairo_t* cr, const Point& c, double radius, double a0, double a1, bool negative) {
  if (!std::isfinite(c.x()) || !std::isfinite(c.y()) || !(radius >= 0) || !std::isfinite(radius)) return;
  // Wholly outside: its box misses the reach box.
  if (std::abs(c.x()) - radius > kReach || std::abs(c.y()) - radius > kReach) return;
  if (std::abs(c.x()) + radius <= kReach && std::abs(c.y()) + radius <= kReach) {
    cairo_new_sub_path(cr);
    (negative ? cairo_arc_negative : cairo_arc)(cr, c.x(), c.y(), radius, a0, a1);
    return;
  }
  // Part of a huge circle: a polyline of it, every tenth of a degree, clipped.
  const double sweep = negative ? -std::fmod(std::fmod(a0 - a1, 2 * M_PI) + 2 * M_PI, 2 * M_PI)
                                : std::fmod(std::fmod(a1 - a0, 2 * M_PI) + 2 * M_PI, 2 * M_PI);
  const double whole = sweep == 0 && a0 != a1 ? 2 * M_PI : sweep;
  const int steps = std::max(2, int(std::ceil(std::abs(whole) / (M_PI / 1800))));
  std::vector<Point> points;
  for (int k = 0; k <= steps; ++k) {
    const double a = a0 + whole * k / steps;
    points.push_back(c + radius * Point(std::cos(a), std::sin(a)));
  }
  cairo_new_sub_path(cr);
  add_polyline(cr, points);
}

}  // namespace vibra::render
