// What a pendulum hangs from: a ceiling while its recorded motion stays below it, else a bearing block nothing reaches.
#include "scenes/diagrams/pendulum/pendulum_support.hpp"

#include <algorithm>
#include <cmath>

#include "render/draw/elements/shapes.hpp"

namespace vibra::scenes {

void PendulumSupport::see(const Point& center, double r) {
  if (!center.allFinite()) return;
  highest_ = std::max(highest_, center.y() + r);
  nearest_ = std::min(nearest_, (center - pivot_).norm() - r);
}

double PendulumSupport::block_half_side() const {
  // The block's corner is sqrt(2) half sides out: 0.6 keeps it inside the nearest edge.
  return std::clamp(0.6 * nearest_, 0.0, kLargestBlock);
}

WorldBox PendulumSupport::region() const {
  if (is_ceiling())
    return WorldBox(pivot_ - Point(kCeilingHalfWidth, 0), Point(pivot_.x() + kCeilingHalfWidth, INFINITY));
  const double h = block_half_side();
  return WorldBox(pivot_ - Point(h, h), pivot_ + Point(h, h));
}

void PendulumSupport::draw(render::Canvas& canvas, const render::WorldView& view, const render::Color& ink) const {
  if (is_ceiling())
    render::draw_ceiling(canvas, view, pivot_, kCeilingHalfWidth, {ink, 2.2});
  else
    render::draw_pivot_block(canvas, view, pivot_, block_half_side(), ink.with_alpha(0.12), {ink, 1.6});
}

}  // namespace vibra::scenes
