// Labelled marks on a drawing: force arrows and dimension lines.
#include "render/draw/annotations.hpp"

#include <cmath>
#include <utility>

#include "render/draw/contrast.hpp"
#include "render/draw/reach_clip.hpp"
#include "render/labels/drawing_record.hpp"
#include "render/labels/label_placer.hpp"

namespace vibra::render {

namespace {
/// 720p pixels: an arrow shorter than this is drawn as a dot (its head alone would be a smear).
constexpr double kShortestArrow = 14;
}  // namespace

bool draw_force_arrow(Canvas& canvas, const WorldView& view, const ForceArrow& f, const Color& background) {
  const double scale = canvas.scale();
  const Point from = view.to_pixel(f.from), tip = view.to_pixel(f.to);
  const bool visible = (tip - from).norm() >= kShortestArrow * scale;
  // A force sits on its casing of the background, whatever body it
  // crosses, in a colour that reads on that background.
  const Color color = legible_on(f.color, background);
  const Casing casing{background, 2.5, f.from_rim};
  {
    OutlineKindScope kind(canvas, OutlineKind::arrow);
    if (visible) {
      draw_arrow(canvas, view, f.from, f.to, {color, kForceShaftWidth}, 22, casing);
    } else {
      // Shorter than its head: a small ring where the force acts, still
      // labelled (a ring, so the body under it keeps its colour).
      for (const auto& [ink, width] :
           {std::pair{background, 2.2 + 2 * casing.device_reach(scale) / scale}, std::pair{color, 2.2}}) {
        cairo_new_path(canvas.cr());
        add_arc(canvas.cr(), from, 5 * scale, 0, 2 * M_PI);
        cairo_set_source_rgba(canvas.cr(), ink.r, ink.g, ink.b, ink.a);
        cairo_set_line_width(canvas.cr(), width * scale);
        cairo_set_dash(canvas.cr(), nullptr, 0, 0);
        canvas.stroke();
      }
    }
  }
  if (f.label.empty()) return visible;
  TextStyle style{24, color};
  style.halo = true, style.halo_color = background;
  if (!visible)
    request_label(canvas, {f.label, style, from, f.place == LabelPlace::beside ? f.side : Point(1, -1), 6 * scale});
  else if (f.place == LabelPlace::beside)
    request_label(canvas, {f.label, style, 0.5 * (from + tip), f.side, 8 * scale});
  else
    request_label(canvas, {f.label, style, tip, tip - from, 5 * scale});
  return visible;
}

void draw_dimension(Canvas& canvas, const WorldView& view, const Point& a, const Point& b, const std::string& label,
                    const Point& side, const Color& color, const Color& background) {
  const double scale = canvas.scale();
  OutlineKindScope kind(canvas, OutlineKind::arrow);
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
      const Point arrowhead[] = {end, base + 0.4 * head * cross, base - 0.4 * head * cross};
      add_polygon(cr, arrowhead);
      cairo_set_source_rgba(cr, color.r, color.g, color.b, color.a);
      canvas.fill();
    }
  } else if (length > 0.5) {
    draw_pixel_line(canvas, pa, pb, thin);
  }
  if (label.empty()) return;
  TextStyle style{20, color};
  style.halo = true, style.halo_color = background;
  request_label(canvas, {label, style, 0.5 * (pa + pb), side, 6 * scale});
}

}  // namespace vibra::render
