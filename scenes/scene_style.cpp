#include "scenes/scene_style.hpp"

#include <cstdio>

#include "render/text.hpp"

namespace vibra::scenes {

void draw_readout(render::Canvas& canvas, const render::PixelRect& area, double t, const SceneStyle& style) {
  const double scale = canvas.scale();
  char text[96];
  if (style.period > 0)
    std::snprintf(text, sizeof text, "<i>t</i> = %.2f   (%.2f periods)", t, t / style.period);
  else
    std::snprintf(text, sizeof text, "<i>t</i> = %.2f", t);
  render::draw_text(canvas, {area.x + 16 * scale, area.y + 14 * scale}, text, {20, style.colors.wire},
                    render::Anchor::top_left);
}

}  // namespace vibra::scenes
