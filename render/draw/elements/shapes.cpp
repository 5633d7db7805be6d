// Basic shapes in world units: strokes, arrows, arcs, circles, polylines, hatched ceilings and the pendulum's pivot.
#include "render/draw/elements/shapes.hpp"

#include <algorithm>
#include <cmath>

#include "render/draw/reach_clip.hpp"
#include "render/labels/drawing_record.hpp"

namespace vibra::render {

namespace {
void apply(Canvas& canvas, const Stroke& s) {
  cairo_t* cr = canvas.cr();
  cairo_set_source_rgba(cr, s.color.r, s.color.g, s.color.b, s.color.a);
  const double width = s.width * canvas.scale();
  cairo_set_line_width(cr, width);
  if (s.dashed) {
    const double dash[] = {4 * width, 3 * width};
    cairo_set_dash(cr, dash, 2, s.dash_offset);
  } else {
    cairo_set_dash(cr, nullptr, 0, 0);
  }
}

/// The axle a pendulum turns on.
void draw_pin(Canvas& canvas, const Point& at, const Color& color) {
  cairo_new_path(canvas.cr());
  add_arc(canvas.cr(), at, 4.5 * canvas.scale(), 0, 2 * M_PI);
  cairo_set_source_rgba(canvas.cr(), color.r, color.g, color.b, color.a);
  canvas.fill();
}
}  // namespace

std::pair<Point, Point> segment_axes(const Point& a, const Point& b) {
  const Point d = b - a;
  const double n = std::hypot(d.x(), d.y());
  const Point along = n > 1e-15 && std::isfinite(n) ? Point(d / n) : Point(1, 0);
  return {along, Point(-along.y(), along.x())};
}

void draw_pixel_line(Canvas& canvas, const Point& a, const Point& b, const Stroke& s) {
  apply(canvas, s);
  const Point ends[] = {a, b};
  add_polyline(canvas.cr(), ends);
  canvas.stroke();
}

void draw_pixel_segments(Canvas& canvas, std::span<const std::pair<Point, Point>> segments, const Stroke& s) {
  if (segments.empty()) return;
  apply(canvas, s);
  for (const auto& [a, b] : segments) {
    const Point ends[] = {a, b};
    add_polyline(canvas.cr(), ends);
  }
  canvas.stroke();
}

void draw_pixel_polyline(Canvas& canvas, std::span<const Point> points, const Stroke& s) {
  if (points.size() < 2) return;
  apply(canvas, s);
  add_polyline(canvas.cr(), points);
  canvas.stroke();
}

void fill_pixel_rect(Canvas& canvas, const PixelRect& r, const Color& c) {
  cairo_set_source_rgba(canvas.cr(), c.r, c.g, c.b, c.a);
  cairo_rectangle(canvas.cr(), r.x, r.y, r.w, r.h);
  canvas.fill();
}

void fill_pixel_disc(Canvas& canvas, const Point& center, double radius, const Color& c) {
  cairo_new_path(canvas.cr());
  cairo_arc(canvas.cr(), center.x(), center.y(), radius, 0, 2 * M_PI);
  cairo_set_source_rgba(canvas.cr(), c.r, c.g, c.b, c.a);
  canvas.fill();
}

void draw_line(Canvas& canvas, const WorldView& view, const Point& a, const Point& b, const Stroke& s) {
  draw_pixel_line(canvas, view.to_pixel(a), view.to_pixel(b), s);
}

void draw_arrow(Canvas& canvas, const WorldView& view, const Point& from, const Point& to, const Stroke& s,
                double head, const std::optional<Casing>& casing) {
  draw_pixel_arrow(canvas, view.to_pixel(from), view.to_pixel(to), s, head, casing);
}

namespace {
/// An arrow's pieces in pixels: the shaft, which stops inside the head so
/// its round cap does not poke out of the tip, and the head's outline.
struct ArrowShape {
  Point shaft_from, shaft_to;
  Point head[4];
};

ArrowShape arrow_shape(const Point& a, const Point& b, double length, double head_length) {
  const Point along = (b - a) / length, across(-along.y(), along.x());
  const double half_width = 0.45 * head_length;
  const Point base = b - head_length * along;
  return {a, b - 0.8 * head_length * along,
          {b, base + half_width * across, base + 0.25 * head_length * along, base - half_width * across}};
}

/// The casing under an arrow: its shaft and head widened by the casing's reach.
void draw_casing(Canvas& canvas, const ArrowShape& shape, double shaft_width, const Casing& casing) {
  const double reach = casing.device_reach(canvas.scale());
  const Color& color = casing.color;
  cairo_t* cr = canvas.cr();
  cairo_save(cr);
  apply(canvas, {color, shaft_width + 2 * reach / canvas.scale()});
  if (casing.square_tail) cairo_set_line_cap(cr, CAIRO_LINE_CAP_BUTT);
  const Point ends[] = {shape.shaft_from, shape.shaft_to};
  add_polyline(cr, ends);
  canvas.stroke();
  cairo_restore(cr);
  cairo_new_path(cr);
  add_polygon(cr, shape.head);
  cairo_set_source_rgba(cr, color.r, color.g, color.b, color.a);
  cairo_set_line_width(cr, 2 * reach);
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  cairo_set_dash(cr, nullptr, 0, 0);
  canvas.fill_preserve();
  canvas.stroke();
}
}  // namespace

void draw_pixel_arrow(Canvas& canvas, const Point& a, const Point& b, const Stroke& s, double head,
                      const std::optional<Casing>& casing) {
  OutlineKindScope outline_kind(canvas, OutlineKind::arrow);
  const double length = (b - a).norm();
  if (length < 1e-9) return;
  const ArrowShape shape = arrow_shape(a, b, length, std::min(head * canvas.scale(), 0.6 * length));
  if (casing) draw_casing(canvas, shape, s.width, *casing);
  draw_pixel_line(canvas, shape.shaft_from, shape.shaft_to, {s.color, s.width, s.dashed});
  cairo_t* cr = canvas.cr();
  add_polygon(cr, shape.head);
  cairo_set_source_rgba(cr, s.color.r, s.color.g, s.color.b, s.color.a);
  canvas.fill();
}

void draw_circle(Canvas& canvas, const WorldView& view, const Point& center, double radius, const Color& fill,
                 const Stroke& outline) {
  OutlineKindScope outline_kind(canvas, OutlineKind::body);
  const Point c = view.to_pixel(center);
  cairo_t* cr = canvas.cr();
  cairo_new_path(cr);
  add_arc(cr, c, radius * view.zoom(), 0, 2 * M_PI);
  cairo_set_source_rgba(cr, fill.r, fill.g, fill.b, fill.a);
  canvas.fill_preserve();
  apply(canvas, outline);
  canvas.stroke();
}

void draw_arc(Canvas& canvas, const WorldView& view, const Point& center, double radius, double a0, double a1,
              const Stroke& s) {
  if (std::abs(a1 - a0) < 1e-12 || !std::isfinite(a1 - a0)) return;
  // A sweep of more than a turn draws as one turn: Cairo makes segments in
  // proportion to the angle, and a pendulum at Theta = 1e9 degrees would
  // cost minutes a frame for the same circle.
  if (std::abs(a1 - a0) > 2 * M_PI) a1 = a0 + std::copysign(2 * M_PI, a1 - a0);
  const Point c = view.to_pixel(center);
  cairo_t* cr = canvas.cr();
  apply(canvas, s);
  cairo_new_path(cr);
  // Pixel y points down, so world angles turn the other way.
  add_arc(cr, c, radius * view.zoom(), -a0, -a1, a1 > a0);
  canvas.stroke();
}

void draw_ceiling(Canvas& canvas, const WorldView& view, const Point& center, double half_width, const Stroke& s) {
  OutlineKindScope outline_kind(canvas, OutlineKind::ground);
  const Point left = view.to_pixel(center - Point(half_width, 0)), right = view.to_pixel(center + Point(half_width, 0));
  const double spacing = 12 * canvas.scale(), rise = 12 * canvas.scale();
  Stroke hatch = s;
  hatch.width = 0.6 * s.width;
  cairo_save(canvas.cr());
  cairo_rectangle(canvas.cr(), left.x(), left.y() - rise, right.x() - left.x(), rise);
  cairo_clip(canvas.cr());
  for (double x = left.x() - rise; x < right.x() + spacing; x += spacing)
    draw_pixel_line(canvas, {x, left.y()}, {x + rise, left.y() - rise}, hatch);
  cairo_restore(canvas.cr());
  Stroke thick = s;
  thick.width = 1.5 * s.width;
  draw_pixel_line(canvas, left, right, thick);
  draw_pin(canvas, view.to_pixel(center), s.color);
}

void draw_pivot_block(Canvas& canvas, const WorldView& view, const Point& center, double half_width, const Color& fill,
                      const Stroke& s) {
  OutlineKindScope outline_kind(canvas, OutlineKind::ground);
  const Point low = view.to_pixel(center - Point(half_width, half_width));
  const Point high = view.to_pixel(center + Point(half_width, half_width));
  const double x = std::min(low.x(), high.x()), y = std::min(low.y(), high.y());
  const double w = std::abs(high.x() - low.x()), h = std::abs(high.y() - low.y());
  const double r = 0.18 * std::min(w, h);
  cairo_t* cr = canvas.cr();
  cairo_new_path(cr);
  cairo_arc(cr, x + w - r, y + r, r, -M_PI / 2, 0);
  cairo_arc(cr, x + w - r, y + h - r, r, 0, M_PI / 2);
  cairo_arc(cr, x + r, y + h - r, r, M_PI / 2, M_PI);
  cairo_arc(cr, x + r, y + r, r, M_PI, 1.5 * M_PI);
  cairo_close_path(cr);
  cairo_set_source_rgba(cr, fill.r, fill.g, fill.b, fill.a);
  canvas.fill_preserve();
  apply(canvas, s);
  canvas.stroke();
  draw_pin(canvas, view.to_pixel(center), s.color);
}

}  // namespace vibra::render
