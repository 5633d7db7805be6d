#include "render/machine_elements.hpp"

#include <algorithm>
#include <cmath>
#include <memory>

namespace vibra::render {

namespace {
/// Unit vector along a -> b and across it (counter-clockwise); along = +x for a == b.
std::pair<Point, Point> axes(const Point& a, const Point& b) {
  const Point d = b - a;
  const double n = d.norm();
  const Point along = n > 1e-15 ? Point(d / n) : Point(1, 0);
  return {along, Point(-along.y(), along.x())};
}

std::vector<Point> to_pixels(const WorldView& view, std::span<const Point> points) {
  std::vector<Point> out;
  out.reserve(points.size());
  for (const Point& p : points) out.push_back(view.to_pixel(p));
  return out;
}

void set_source(Canvas& canvas, const Color& c) { cairo_set_source_rgba(canvas.cr(), c.r, c.g, c.b, c.a); }
}  // namespace

std::vector<Point> spring_points(const Point& from, const Point& to, const SpringShape& s) {
  const auto [along, across] = axes(from, to);
  const double length = (to - from).norm();
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
  const std::vector<Point> points = spring_points(from, to, shape);
  const std::vector<Point> pixels = to_pixels(view, points);
  cairo_set_line_join(canvas.cr(), CAIRO_LINE_JOIN_ROUND);
  draw_pixel_polyline(canvas, pixels, stroke);
  cairo_set_line_join(canvas.cr(), CAIRO_LINE_JOIN_MITER);
}

DashpotGeometry dashpot_geometry(const Point& from, const Point& to, const DashpotShape& s) {
  const auto [along, across] = axes(from, to);
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
  draw_circle(canvas, view, center, radius, fill, stroke);
  Stroke spoke = stroke;
  spoke.width = 0.7 * stroke.width;
  for (int i = 0; i < 3; ++i) {
    const double a = angle + i * M_PI / 3;
    const Point d(std::cos(a), std::sin(a));
    draw_line(canvas, view, center - 0.82 * radius * d, center + 0.82 * radius * d, spoke);
  }
  draw_circle(canvas, view, center, 0.16 * radius, stroke.color, stroke);
}

void draw_box(Canvas& canvas, const WorldView& view, const Point& low, const Point& high, const Color& fill,
              const Stroke& stroke) {
  const Point a = view.to_pixel(Point(low.x(), high.y())), b = view.to_pixel(Point(high.x(), low.y()));
  cairo_t* cr = canvas.cr();
  cairo_new_path(cr);
  cairo_rectangle(cr, a.x(), a.y(), b.x() - a.x(), b.y() - a.y());
  set_source(canvas, fill);
  canvas.fill_preserve();
  cairo_set_source_rgba(cr, stroke.color.r, stroke.color.g, stroke.color.b, stroke.color.a);
  cairo_set_line_width(cr, stroke.width * canvas.scale());
  cairo_set_dash(cr, nullptr, 0, 0);
  canvas.stroke();
}

void draw_hatched_surface(Canvas& canvas, const WorldView& view, const Point& a, const Point& b, const Point& outside,
                          const Stroke& s) {
  const Point pa = view.to_pixel(a), pb = view.to_pixel(b);
  const Point out_pixels = Point(outside.x(), -outside.y()).normalized();
  const double spacing = 12 * canvas.scale(), depth = 12 * canvas.scale();
  const auto [along, across] = axes(pa, pb);
  const double length = (pb - pa).norm();
  Stroke hatch = s;
  hatch.width = 0.6 * s.width;
  cairo_t* cr = canvas.cr();
  cairo_save(cr);
  cairo_new_path(cr);
  cairo_move_to(cr, pa.x(), pa.y());
  cairo_line_to(cr, pb.x(), pb.y());
  const Point qb = pb + depth * out_pixels, qa = pa + depth * out_pixels;
  cairo_line_to(cr, qb.x(), qb.y());
  cairo_line_to(cr, qa.x(), qa.y());
  cairo_close_path(cr);
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

namespace {
/// One period of a ground's fill: a tile `period` pixels square, the pale
/// `fill` crossed by hatches rising to the right (the lines u + v = k period).
/// Repeated, the hatches run on unbroken across tiles.
std::shared_ptr<cairo_surface_t> hatch_tile(int period, const Color& fill, const Stroke& hatch, double scale) {
  std::shared_ptr<cairo_surface_t> tile(cairo_image_surface_create(CAIRO_FORMAT_ARGB32, period, period),
                                        cairo_surface_destroy);
  cairo_t* cr = cairo_create(tile.get());
  cairo_set_antialias(cr, CAIRO_ANTIALIAS_GOOD);  // as the canvas draws
  cairo_set_source_rgba(cr, fill.r, fill.g, fill.b, fill.a);
  cairo_paint(cr);
  cairo_set_source_rgba(cr, hatch.color.r, hatch.color.g, hatch.color.b, hatch.color.a);
  cairo_set_line_width(cr, hatch.width * scale);
  for (int k = 0; k <= 2; ++k) {  // k = 0 and 2 reach the corners
    cairo_move_to(cr, -2, k * period + 2);
    cairo_line_to(cr, k * period + 2, -2);
  }
  cairo_stroke(cr);
  cairo_destroy(cr);
  cairo_surface_flush(tile.get());
  return tile;
}
}  // namespace

void draw_ground_profile(Canvas& canvas, const WorldView& view, const std::function<double(double)>& height, double step,
                         double depth, const Stroke& s) {
  cairo_t* cr = canvas.cr();
  double clip_x0, clip_y0, clip_x1, clip_y1;
  cairo_clip_extents(cr, &clip_x0, &clip_y0, &clip_x1, &clip_y1);
  // The road's points at whole multiples of `step`, one beyond each side of
  // the visible part.
  const double zoom = view.zoom(), origin = view.to_pixel(Point(0, 0)).x();
  const double reach = 2 * s.width * canvas.scale();
  if (!(step > 0)) return;
  const auto first = static_cast<long long>(std::floor((clip_x0 - reach - origin) / zoom / step));
  const auto last = static_cast<long long>(std::ceil((clip_x1 + reach - origin) / zoom / step));
  if (last - first > 1'000'000) return;
  std::vector<Point> top;
  top.reserve(size_t(last - first + 1));
  for (long long i = first; i <= last; ++i) top.push_back(view.to_pixel(Point(i * step, height(i * step))));
  if (top.size() < 2) return;
  double low = top.front().y();  // the road's highest point, in pixel rows
  for (const Point& p : top) low = std::min(low, p.y());
  // The band ends below the visible part: deeper would not show.
  const double drop = std::min(depth * zoom, std::max(0.0, clip_y1 + reach - low));

  // The solid under the road: a pale band, hatched. The hatching is a tile
  // repeated from a whole pixel near the world's origin, so it moves with the
  // road; one fill paints it (stroking each hatch cut to the band would cost
  // Cairo many times more).
  Stroke hatch = s;
  hatch.width = 0.5 * s.width;
  hatch.color = s.color.with_alpha(0.35);
  const int period = std::max(4, static_cast<int>(std::lround(14 * canvas.scale())));
  const std::shared_ptr<cairo_surface_t> tile = hatch_tile(period, s.color.with_alpha(0.08), hatch, canvas.scale());
  cairo_pattern_t* fill = cairo_pattern_create_for_surface(tile.get());
  cairo_pattern_set_extend(fill, CAIRO_EXTEND_REPEAT);
  cairo_pattern_set_filter(fill, CAIRO_FILTER_NEAREST);
  cairo_matrix_t shift;
  cairo_matrix_init_translate(&shift, -std::round(origin), 0);
  cairo_pattern_set_matrix(fill, &shift);
  cairo_new_path(cr);
  cairo_move_to(cr, top.front().x(), top.front().y());
  for (const Point& p : top) cairo_line_to(cr, p.x(), p.y());
  for (auto p = top.rbegin(); p != top.rend(); ++p) cairo_line_to(cr, p->x(), p->y() + drop);
  cairo_close_path(cr);
  cairo_set_source(cr, fill);
  canvas.fill();
  cairo_pattern_destroy(fill);

  Stroke line = s;
  line.width = 1.4 * s.width;
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  draw_pixel_polyline(canvas, top, line);
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_MITER);
}

}  // namespace vibra::render
