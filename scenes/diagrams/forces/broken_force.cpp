// A force arrow drawn to its run's scale, or clipped to the room its part has with a break mark across its shaft.
#include "scenes/diagrams/forces/broken_force.hpp"

#include "render/draw/elements/shapes.hpp"
#include "render/labels/drawing_record.hpp"

namespace vibra::scenes {

namespace {
/// Two strokes across the shaft from `from` to `tip` (pixels) at 60% of its
/// length, slanted like a break in a dimension line, over a gap in the shaft.
void draw_break_mark(render::Canvas& canvas, const Point& from, const Point& tip, const render::Color& ink,
                     const render::Color& background) {
  const double scale = canvas.scale();
  const Point along = (tip - from).normalized(), across(-along.y(), along.x());
  const Point middle = from + 0.6 * (tip - from);
  const Point gap = 3.5 * scale * along, slant = 8 * scale * across + 3 * scale * along;
  render::draw_pixel_line(canvas, middle - gap, middle + gap, {background, 4.5});
  for (const Point& at : {Point(middle - gap), Point(middle + gap)})
    render::draw_pixel_line(canvas, at - slant, at + slant, {ink, 2});
}
}  // namespace

bool draw_broken_force(render::Canvas& canvas, const render::WorldView& view, double room, render::ForceArrow f,
                       const render::Color& background) {
  const Arrow drawn = ForceScale::clipped({f.from, f.to}, room);
  const bool broken = drawn.to != f.to;
  f.to = drawn.to;
  render::draw_force_arrow(canvas, view, f, background);
  if (broken) {
    render::OutlineKindScope kind(canvas, render::OutlineKind::arrow);
    draw_break_mark(canvas, view.to_pixel(f.from), view.to_pixel(f.to), f.color, background);
  }
  return broken;
}

}  // namespace vibra::scenes
