#include "render/annotations.hpp"

#include <cmath>

namespace vibra::render {

bool draw_force_arrow(Canvas& canvas, const WorldView& view, const ForceArrow& f, const Color& background) {
  const double scale = canvas.scale();
  const Point from = view.to_pixel(f.from), tip = view.to_pixel(f.to);
  if ((tip - from).norm() < 8 * scale) return false;
  draw_arrow(canvas, view, f.from, f.to, {f.color, 4.2}, 22);
  if (f.label.empty()) return true;
  TextStyle style{24, f.color};
  style.halo = true, style.halo_color = background;
  const Point size = text_size(canvas, f.label, style);
  const Point at = f.place == LabelPlace::beside ? label_beyond(0.5 * (from + tip), f.side, size, 8 * scale)
                                                 : label_beyond(tip, tip - from, size, 5 * scale);
  draw_text(canvas, at, f.label, style);
  return true;
}

void draw_dimension(Canvas& canvas, const WorldView& view, const Point& a, const Point& b, const std::string& label,
                    const Point& side, const Color& color, const Color& background) {
  const double scale = canvas.scale();
  const Point pa = view.to_pixel(a), pb = view.to_pixel(b);
  const Point d = pb - pa;
  const double length = d.norm();
  const Point along = length > 1e-9 ? Point(d / length) : Point(1, 0), across(-along.y(), along.x());
  const Stroke thin{color, 1.4};
  const double tick = 9 * scale;
  draw_pixel_line(canvas, pa - tick * across, pa + tick * across, thin);
  draw_pixel_line(canvas, pb - tick * across, pb + tick * across, thin);
  const double head = 10 * scale;
  if (length > 2.5 * head) {
    // Heads point outward to both ticks from the middle.
    const Point middle = 0.5 * (pa + pb);
    for (const Point& end : {pa, pb}) {
      const Point dir = (end - middle).normalized(), cross(-dir.y(), dir.x());
      const Point base = end - head * dir;
      draw_pixel_line(canvas, middle, base, thin);
      cairo_t* cr = canvas.cr();
      cairo_new_path(cr);
      cairo_move_to(cr, end.x(), end.y());
      cairo_line_to(cr, base.x() + 0.4 * head * cross.x(), base.y() + 0.4 * head * cross.y());
      cairo_line_to(cr, base.x() - 0.4 * head * cross.x(), base.y() - 0.4 * head * cross.y());
      cairo_close_path(cr);
      cairo_set_source_rgba(cr, color.r, color.g, color.b, color.a);
      canvas.fill();
    }
  } else if (length > 0.5) {
    draw_pixel_line(canvas, pa, pb, thin);
  }
  if (label.empty()) return;
  TextStyle style{20, color};
  style.halo = true, style.halo_color = background;
  const Point size = text_size(canvas, label, style);
  draw_text(canvas, label_beyond(0.5 * (pa + pb), side, size, 6 * scale), label, style);
}

}  // namespace vibra::render
