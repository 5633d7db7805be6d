// Outline: the shape of a recorded piece of a drawing and what it is, for the placer and for checks.
#include "render/labels/outline.hpp"

#include <algorithm>
#include <cmath>

namespace vibra::render {

const char* outline_kind_name(OutlineKind kind) {
  switch (kind) {
    case OutlineKind::drawing: return "drawing";
    case OutlineKind::body: return "body";
    case OutlineKind::spring: return "spring";
    case OutlineKind::wire: return "wire";
    case OutlineKind::arrow: return "arrow";
    case OutlineKind::ground: return "ground";
    case OutlineKind::label: return "label";
    case OutlineKind::legend: return "legend";
    case OutlineKind::text: return "text";
    case OutlineKind::formula: return "formula";
  }
  return "drawing";
}

namespace {
/// The flattened current path in device pixels, one polyline per subpath
/// (closed subpaths end where they began).
std::vector<std::vector<Point>> flat_subpaths(cairo_t* cr) {
  std::vector<std::vector<Point>> out;
  cairo_path_t* path = cairo_copy_path_flat(cr);
  if (path->status == CAIRO_STATUS_SUCCESS) {
    Point start(0, 0);
    for (int i = 0; i < path->num_data; i += path->data[i].header.length) {
      const cairo_path_data_t& d = path->data[i];
      auto device = [&](const cairo_path_data_t& p) {
        double x = p.point.x, y = p.point.y;
        cairo_user_to_device(cr, &x, &y);
        return Point(x, y);
      };
      switch (d.header.type) {
        case CAIRO_PATH_MOVE_TO:
          start = device(path->data[i + 1]);
          out.push_back({start});
          break;
        case CAIRO_PATH_LINE_TO:
          if (out.empty()) out.push_back({start});
          out.back().push_back(device(path->data[i + 1]));
          break;
        case CAIRO_PATH_CLOSE_PATH:
          if (!out.empty() && out.back().size() > 1) out.back().push_back(out.back().front());
          break;
        case CAIRO_PATH_CURVE_TO: break;  // none in a flattened path
      }
    }
  }
  cairo_path_destroy(path);
  return out;
}

PixelRect bounds_of(const std::vector<std::pair<Point, Point>>& segments, double widen) {
  double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
  for (const auto& [a, b] : segments)
    for (const Point& p : {a, b}) x0 = std::min(x0, p.x()), y0 = std::min(y0, p.y()), x1 = std::max(x1, p.x()), y1 = std::max(y1, p.y());
  if (x0 > x1) return {};
  return {x0 - widen, y0 - widen, x1 - x0 + 2 * widen, y1 - y0 + 2 * widen};
}

std::vector<std::pair<Point, Point>> segments_of(const std::vector<std::vector<Point>>& polylines) {
  std::vector<std::pair<Point, Point>> out;
  for (const auto& line : polylines) {
    if (line.size() == 1) out.emplace_back(line[0], line[0]);  // a dot: a round cap still marks it
    for (size_t k = 1; k < line.size(); ++k) out.emplace_back(line[k - 1], line[k]);
  }
  return out;
}

bool intersects(const PixelRect& a, const PixelRect& b) {
  return a.x < b.x + b.w && b.x < a.x + a.w && a.y < b.y + b.h && b.y < a.y + a.h;
}

bool inside(const PixelRect& r, const Point& p) {
  return p.x() >= r.x && p.x() <= r.x + r.w && p.y() >= r.y && p.y() <= r.y + r.h;
}

/// Even-odd rule.
bool inside(const std::vector<Point>& polygon, const Point& p) {
  bool in = false;
  for (size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
    const Point &a = polygon[i], &b = polygon[j];
    if ((a.y() > p.y()) != (b.y() > p.y()) && p.x() < (b.x() - a.x()) * (p.y() - a.y()) / (b.y() - a.y()) + a.x())
      in = !in;
  }
  return in;
}

/// Whether segments p-q and a-b cross (proper or touching).
bool crosses(const Point& p, const Point& q, const Point& a, const Point& b) {
  auto cross = [](const Point& o, const Point& u, const Point& v) {
    return (u.x() - o.x()) * (v.y() - o.y()) - (u.y() - o.y()) * (v.x() - o.x());
  };
  const double d1 = cross(a, b, p), d2 = cross(a, b, q), d3 = cross(p, q, a), d4 = cross(p, q, b);
  return ((d1 > 0) != (d2 > 0) || d1 == 0 || d2 == 0) && ((d3 > 0) != (d4 > 0) || d3 == 0 || d4 == 0) &&
         std::min(p.x(), q.x()) <= std::max(a.x(), b.x()) && std::min(a.x(), b.x()) <= std::max(p.x(), q.x()) &&
         std::min(p.y(), q.y()) <= std::max(a.y(), b.y()) && std::min(a.y(), b.y()) <= std::max(p.y(), q.y());
}

/// Distance from the segment a-b to the rectangle (0 when they meet).
double distance_to_rect(const Point& a, const Point& b, const PixelRect& r) {
  if (inside(r, a) || inside(r, b)) return 0;
  const Point corners[] = {{r.x, r.y}, {r.x + r.w, r.y}, {r.x + r.w, r.y + r.h}, {r.x, r.y + r.h}};
  for (int i = 0; i < 4; ++i)
    if (crosses(a, b, corners[i], corners[(i + 1) % 4])) return 0;
  double d = 1e300;
  for (const Point& c : corners) d = std::min(d, distance_to_segment(c, a, b));
  for (const Point& p : {a, b}) {
    const double dx = std::max({r.x - p.x(), 0.0, p.x() - r.x - r.w}), dy = std::max({r.y - p.y(), 0.0, p.y() - r.y - r.h});
    d = std::min(d, std::hypot(dx, dy));
  }
  return d;
}
}  // namespace

double distance_to_segment(const Point& p, const Point& a, const Point& b) {
  const Point ab = b - a;
  const double length2 = ab.squaredNorm();
  const double s = length2 > 0 ? std::clamp((p - a).dot(ab) / length2, 0.0, 1.0) : 0.0;
  return (p - (a + s * ab)).norm();
}

void Outline::add_stroke(cairo_t* cr, OutlineKind kind) {
  OutlineShape shape{kind, segments_of(flat_subpaths(cr)), 0, {}, {}, {}};
  if (shape.segments.empty()) return;
  double width = cairo_get_line_width(cr), zero = 0;
  cairo_user_to_device_distance(cr, &width, &zero);
  shape.half_width = 0.5 * std::abs(width);
  shape.bounds = bounds_of(shape.segments, shape.half_width);
  shapes_.push_back(std::move(shape));
}

void Outline::add_fill(cairo_t* cr, OutlineKind kind) {
  std::vector<std::vector<Point>> polygons = flat_subpaths(cr);
  std::erase_if(polygons, [](const auto& p) { return p.size() < 3; });
  if (polygons.empty()) return;
  OutlineShape shape{kind, segments_of(polygons), 0, std::move(polygons), {}, {}};
  shape.bounds = bounds_of(shape.segments, 0);
  shapes_.push_back(std::move(shape));
}

void Outline::add_box(const PixelRect& r, OutlineKind kind, std::string name) {
  const Point a(r.x, r.y), b(r.x + r.w, r.y), c(r.x + r.w, r.y + r.h), d(r.x, r.y + r.h);
  shapes_.push_back({kind, {{a, b}, {b, c}, {c, d}, {d, a}}, 0, {{a, b, c, d, a}}, r, std::move(name)});
}

void Outline::add_polygon(std::vector<Point> polygon, OutlineKind kind) {
  if (polygon.size() < 3) return;
  polygon.push_back(polygon.front());
  OutlineShape shape{kind, segments_of({polygon}), 0, {std::move(polygon)}, {}, {}};
  shape.bounds = bounds_of(shape.segments, 0);
  shapes_.push_back(std::move(shape));
}

void Outline::append(const Outline& other) { shapes_.insert(shapes_.end(), other.shapes_.begin(), other.shapes_.end()); }

bool overlaps(const PixelRect& rect, const OutlineShape& shape) {
  if (!intersects(rect, shape.bounds)) return false;
  for (const auto& [a, b] : shape.segments) {
    const double d = distance_to_rect(a, b, rect);
    if (d == 0 || d < shape.half_width) return true;
  }
  for (const auto& polygon : shape.polygons)
    if (inside(polygon, rect.center())) return true;
  return false;
}

}  // namespace vibra::render
