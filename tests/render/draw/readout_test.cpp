// The time read-out, set piece by piece from kept labels, lands exactly where
// Pango sets the whole line.
#include <catch2/catch.hpp>
#include <cstdio>
#include <cstring>

#include "render/draw/canvas.hpp"
#include "render/draw/text.hpp"
#include "scenes/config/scene_style.hpp"

using namespace vibra;

TEST_CASE("read-out: piece by piece, the pixels of the whole line", "[scene][text]") {
  for (const int height : {360, 720, 1080, 2160}) {
    const int width = height * 16 / 9;
    scenes::SceneStyle style;
    for (double t : {0.0, 0.004, 1.0, 2.37, 9.995, 17.5, 31.05, 44.44, 123.46, 777.77, 1008.3}) {
      // Full height: a canvas's height sets its scale (a short one would be a thumbnail's).
      render::Canvas pieces = render::Canvas::image(width / 2, height), whole = render::Canvas::image(width / 2, height);
      pieces.clear(render::palette::paper), whole.clear(render::palette::paper);
      const render::PixelRect area{0, 0, double(width / 2), double(height / 8)};
      scenes::draw_readout(pieces, area, t, style);
      char line[96];
      std::snprintf(line, sizeof line, "<i>t</i> = %.2f   (%.2f periods)", t, t / style.period);
      const double scale = whole.scale();
      render::draw_text(whole, {16 * scale, 14 * scale}, line, {20, style.colors.wire}, render::Anchor::top_left);
      pieces.flush(), whole.flush();
      INFO(height << "p, t = " << t);
      bool same = true;
      for (int y = 0; y < pieces.height() && same; ++y)
        same = std::memcmp(pieces.data() + y * pieces.stride(), whole.data() + y * whole.stride(), 4 * pieces.width()) == 0;
      CHECK(same);
    }
  }
}
