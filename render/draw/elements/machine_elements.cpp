// The machine elements of the chapter's drawings (Figs 1.17, 1.18 and section 1.12): springs, dashpots, wheels, boxes, hatched floors and walls, road profiles.
#include "render/draw/elements/machine_elements.hpp"

#include <algorithm>
#include <cmath>

#include "render/draw/reach_clip.hpp"
#include "render/labels/drawing_record.hpp"

namespace vibra::render {

namespace {
std::vector<Point> to_pixels(const WorldView& view, std::span<const Point> points) {
  std::vector<Point> out;
  out.reserve(points.size());
  for (const Point& p : points) out.push_back(view.to_pixel(p));
  return out;
}

void set_source(Canvas& canvas, const Color& c) { cairo_set_source_rgba(canvas.cr(), c.r, c.g, c.b, c.a); }
}  // namespace

std::vector<Point> spring_points(const Point& from, const Point& to, const SpringShape& s) {
  const auto [along, across] = segment_axes(from, to);
  const double length = std::hypot(to.x() - from.x(), to.y() - from.y());
  const double lead = std::min(s.lead, 0.25 * length);
  const double coil_length = length - 2 * lead;
  const int zigs = 2 * std::max(1, s.coils);
  std::vector<Point> points;
  points.reserve(zigs + 3);
  points.push_back(from);
  points.push_back(from + lead * along);
  // Each half coil goes out to one side and back; the peaks sit at the
  // middle of each half, so the zigzag starts and ends on the axis.
  for (int i = 0; i < zigs; ++i) {
    const double f = (i + 0.5) / zigs;
    const double sign = i % 2 == 0 ? 1 : -1;
    points.push_back(from + (lead + f * coil_length) * along + sign * 0.5 * s.width * across);
  }
  points.push_back(to - lead * along);
  points.push_back(to);
  return points;
}

void draw_spring(Canvas& canvas, const WorldView& view, const Point& from, const Point& to, const SpringShape& shape,
                 const Stroke& stroke) {
  OutlineKindScope outline_kind(canvas, OutlineKind::spring);
  const std::vector<Point> points = spring_points(from, to, shape);
  const std::vector<Point> pixels = to_pixels(view, points);
  cairo_set_line_join(canvas.cr(), CAIRO_LINE_JOIN_ROUND);
  draw_pixel_polyline(canvas, pixels, stroke);
  cairo_set_line_join(canvas.cr(), CAIRO_LINE_JOIN_MITER);
}

DashpotGeometry dashpot_geometry(const Point& from, const Point& to, const DashpotShape& s) {
  const auto [along, across] = segment_axes(from, to);
  const double rest = s.rest_length, cylinder = s.cylinder * rest;
  // At rest the cylinder spans the middle of the distance and the piston
  // sits at its middle; both rods keep their rest lengths.
  const double rod_from = 0.5 * (rest - cylinder);
  const double rod_to = rest - rod_from - 0.5 * cylinder;
  const double half = 0.5 * s.width;
  DashpotGeometry g;
  g.rod_from_start = from;
  g.rod_from_end = from + rod_from * along;
  const Point bottom = g.rod_from_end, mouth = bottom + cylinder * along;
  g.cylinder = {mouth + half * across, bottom + half * across, bottom - half * across, mouth - half * across};
  // The piston may not leave the cylinder however far the ends move.
  const double piston_at = std::clamp((to - from).dot(along) - rod_to, rod_from + 0.06 * cylinder, rod_from + cylinder);
  const Point piston = from + piston_at * along;
  g.piston_a = piston + 0.8 * half * across;
  g.piston_b = piston - 0.8 * half * across;
  g.rod_to_start = piston;
  g.rod_to_end = to;
  return g;
}

void draw_dashpot(Canvas& canvas, const WorldView& view, const Point& from, const Point& to, const DashpotShape& shape,
                  const Stroke& stroke) {
  OutlineKindScope outline_kind(canvas, OutlineKind::spring);
  const DashpotGeometry g = dashpot_geometry(from, to, shape);
  draw_line(canvas, view, g.rod_from_start, g.rod_from_end, stroke);
  const std::vector<Point> cylinder = to_pixels(view, g.cylinder);
  draw_pixel_polyline(canvas, cylinder, stroke);
  Stroke plate = stroke;
  plate.width = 1.6 * stroke.width;
  draw_line(canvas, view, g.piston_a, g.piston_b, plate);
  draw_line(canvas, view, g.rod_to_start, g.rod_to_end, stroke);
}

void draw_wheel(Canvas& canvas, const WorldView& view, const Point& center, double radius, double angle,
                const Color& fill, const Stroke& stroke) {
  OutlineKindScope outline_kind(canvas, OutlineKind::body);
  draw_circle(canvas, view, center, radius, fill, stroke);
  Stroke spoke = stroke;
  spoke.width = 0.7 * stroke.width;
  std::pair<Point, Point> spokes[3];  // one stroke for the three: the hub covers where they cross
  for (int i = 0; i < 3; ++i) {
    const double a = angle + i * M_PI / 3;
    const Point d(std::cos(a), std::sin(a));
    spokes[i] = {view.to_pixel(center - 0.82 * radius * d), view.to_pixel(center + 0.82 * radius * d)};
  }
  draw_pixel_segments(canvas, spokes, spoke);
  // The hub covers where the spokes cross: filled and outlined in one
  // colour, so one disc as wide as fill and outline together.
  const Point hub = view.to_pixel(center);
  cairo_t* cr = canvas.cr();
  cairo_new_path(cr);
  add_arc(cr, hub, 0.16 * radius * view.zoom() + 0.5 * stroke.width * canvas.scale(), 0, 2 * M_PI);
  set_source(canvas, stroke.color);
  canvas.fill();
}

void draw_box(Canvas& canvas, const WorldView& view, const Point& low, const Point& high, const Color& fill,
              const Stroke& stroke) {
  OutlineKindScope outline_kind(canvas, OutlineKind::body);
  const Point a = view.to_pixel(Point(low.x(), high.y())), b = view.to_pixel(Point(high.x(), low.y()));
  cairo_t* cr = canvas.cr();
  cairo_new_path(cr);
  if (within_reach(a) && within_reach(b)) {  // Cairo's own box path: the bits every frame had before
    cairo_rectangle(cr, a.x(), a.y(), b.x() - a.x(), b.y() - a.y());
  } else {
    const Point corners[] = {a, Point(b.x(), a.y()), b, Point(a.x(), b.y())};
    add_polygon(cr, corners);
  }
  set_source(canvas, fill);
  canvas.fill_preserve();
  cairo_set_source_rgba(cr, stroke.color.r, stroke.color.g, stroke.color.b, stroke.color.a);
  cairo_set_line_width(cr, stroke.width * canvas.scale());
  cairo_set_dash(cr, nullptr, 0, 0);
  canvas.stroke();
}

void draw_hatched_surface(Canvas& canvas, const WorldView& view, const Point& a, const Point& b, const Point& outside,
                          const Stroke& s) {
  OutlineKindScope outline_kind(canvas, OutlineKind::ground);
  const Point pa = view.to_pixel(a), pb = view.to_pixel(b);
  const Point out_pixels = Point(outside.x(), -outside.y()).normalized();
  const double spacing = 12 * canvas.scale(), depth = 12 * canvas.scale();
  const auto [along, across] = segment_axes(pa, pb);
  const double length = (pb - pa).norm();
  Stroke hatch = s;
  hatch.width = 0.6 * s.width;
  cairo_t* cr = canvas.cr();
  cairo_save(cr);
  cairo_new_path(cr);
  const Point qb = pb + depth * out_pixels, qa = pa + depth * out_pixels;
  const Point band[] = {pa, pb, qb, qa};
  add_polygon(cr, band);
  cairo_clip(cr);
  // Short strokes slanting away from the surface, as on an engineering drawing.
  const Point slant = (depth * out_pixels + 0.8 * depth * along);
  for (double d = -depth; d < length + spacing; d += spacing) {
    const Point p = pa + d * along;
    draw_pixel_line(canvas, p, p + slant, hatch);
  }
  cairo_restore(cr);
  Stroke thick = s;
  thick.width = 1.5 * s.width;
  draw_pixel_line(canvas, pa, pb, thick);
  (void)across;
}

}  // namespace vibra::render
