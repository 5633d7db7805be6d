// SceneStyle: what every scene shares: layout (fbd, fbd+plot, plot, grid), colours, plot window, time read-out.
#include "scenes/config/scene_style.hpp"

#include <cstdio>

#include "render/draw/text.hpp"

namespace vibra::scenes {

void draw_readout(render::Canvas& canvas, const render::PixelRect& area, double t, const SceneStyle& style) {
  const double scale = canvas.scale();
  char time[32], periods[32] = "";
  std::snprintf(time, sizeof time, "%.2f", t);
  if (style.period > 0) std::snprintf(periods, sizeof periods, "%.2f", t / style.period);
  // Set piece by piece, each piece a label kept from frame to frame and the
  // numbers digit by digit, so a frame lays out no text. DejaVu Sans has
  // figures of one width and no kerning between these characters: the pieces
  // land where Pango sets the whole line.
  const render::TextStyle text{20, style.colors.wire};
  render::Point at(area.x + 16 * scale, area.y + 14 * scale);
  auto piece = [&](const std::string& markup) {
    at.x() += render::draw_text(canvas, at, markup, text, render::Anchor::top_left).x();
  };
  piece("<i>t</i> = ");
  for (const char* c = time; *c; ++c) piece(std::string(1, *c));
  if (!*periods) return;
  piece("   (");
  for (const char* c = periods; *c; ++c) piece(std::string(1, *c));
  piece(" periods)");
}

}  // namespace vibra::scenes
