// Readable in a hall: contrast ratios from the WCAG 2 formula, and every force arrow and label of every scene measured on the drawn pixels against what it sits on.
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "render/draw/canvas.hpp"
#include "render/draw/color.hpp"
#include "render/draw/contrast.hpp"
#include "scene_run_support.hpp"
#include "scenes/config/scene_config.hpp"
#include "scenes/scene_factory.hpp"

using vibra::render::Color;
using vibra::render::contrast_ratio;
using vibra::render::legible_on;
namespace palette = vibra::render::palette;

TEST_CASE("contrast ratios are WCAG 2's: 21 black on white, 1 alike, 4.54 for #767676 on white",
          "[contrast]") {
  CHECK(contrast_ratio({0, 0, 0}, {1, 1, 1}) == Approx(21));
  CHECK(contrast_ratio({1, 1, 1}, {0, 0, 0}) == Approx(21));
  CHECK(contrast_ratio(palette::blue, palette::blue) == Approx(1));
  const double grey = 0x76 / 255.0;  // the web's well-known darkest grey that passes 4.5:1 on white
  CHECK(contrast_ratio({grey, grey, grey}, {1, 1, 1}) == Approx(4.54).margin(0.01));
  // Mid grey #808080: L = ((0.50196 + 0.055) / 1.055)^2.4 = 0.21586.
  const double mid = 0x80 / 255.0;
  CHECK(contrast_ratio({mid, mid, mid}, {1, 1, 1}) == Approx(1.05 / (0.21586 + 0.05)).epsilon(1e-4));
}

TEST_CASE("legible_on keeps a colour that reads and darkens or lightens one that does not, no more than it must",
          "[contrast]") {
  const Color paper{1, 1, 1}, night{0, 0, 0}, slate{0.35, 0.35, 0.38};
  CHECK(legible_on(palette::vermillion, paper) == palette::vermillion);  // 3.8:1 already
  struct Case {
    Color ink, ground;
  };
  for (const Case& c : {Case{palette::yellow, paper}, Case{palette::orange, paper}, Case{palette::sky, paper},
                        Case{palette::ink, night}, Case{palette::charcoal, night}, Case{palette::green, palette::blue},
                        Case{Color{0.9, 0.9, 0.9}, Color{0.8, 0.8, 0.8}}, Case{slate, Color{0.3, 0.3, 0.3}}}) {
    const Color made = legible_on(c.ink, c.ground);
    INFO("ink " << c.ink.r << "," << c.ink.g << "," << c.ink.b << " on " << c.ground.r << "," << c.ground.g << ","
                << c.ground.b);
    CHECK(contrast_ratio(made, c.ground) >= 3.0);
    CHECK(contrast_ratio(made, c.ground) < 3.1);  // the least change that reaches 3:1 (and a margin for 8 bits)
    // The hue is kept: the channels keep their order.
    CHECK((made.r >= made.g) == (c.ink.r >= c.ink.g));
    CHECK((made.g >= made.b) == (c.ink.g >= c.ink.b));
  }
  CHECK(legible_on(palette::yellow, paper).a == 1);
  CHECK(legible_on(palette::yellow.with_alpha(0.5), paper).a == 0.5);
}

namespace {

std::uint32_t word(const vibra::render::Canvas& canvas, int x, int y) {
  std::uint32_t w;
  std::memcpy(&w, canvas.data() + std::size_t(y) * canvas.stride() + 4 * std::size_t(x), 4);
  return w;
}

bool same(const Color& a, const Color& b) {
  const double tolerance = 3.5 / 255;
  return std::abs(a.r - b.r) <= tolerance && std::abs(a.g - b.g) <= tolerance && std::abs(a.b - b.b) <= tolerance;
}

Color colour_of(std::uint32_t argb) {  // an opaque frame's pixel
  return {((argb >> 16) & 255) / 255.0, ((argb >> 8) & 255) / 255.0, (argb & 255) / 255.0};
}

/// How a mark fares against what it sits on, measured on two renders of
/// one frame that differ only in the mark's colour (the other inverted):
/// the pixels that differ are the ones painted in that colour, fringes of
/// antialiasing and pale fills of it included. The mark's ink is the most
/// contrasting of the colours they show in number (its fully covered
/// pixels); its ground is every untouched pixel within 2 pixels of an ink
/// pixel: past the fringe, where a casing or a halo lies when there is one.
struct GroundReport {
  long touched = 0, ground = 0, faint = 0;  ///< pixel counts: the mark, its ground, ground under 3:1
  Color ink;
  int x = -1, y = -1;  ///< the faintest ground pixel
  Color worst{1, 1, 1};
};

GroundReport ground_of(const vibra::render::Canvas& frame, const vibra::render::Canvas& other, const Color& background) {
  const int w = frame.width(), h = frame.height();
  std::vector<unsigned char> touched(std::size_t(w) * h), ink(std::size_t(w) * h);
  std::map<std::uint32_t, long> colour_counts;
  GroundReport r;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      if (word(frame, x, y) != word(other, x, y)) touched[std::size_t(y) * w + x] = 1, ++r.touched, ++colour_counts[word(frame, x, y)];
  double most = 0;
  for (const auto& [argb, count] : colour_counts)
    if (count >= 10 && contrast_ratio(colour_of(argb), background) > most) most = contrast_ratio(colour_of(argb), background), r.ink = colour_of(argb);
  if (most == 0) return r;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) ink[std::size_t(y) * w + x] = touched[std::size_t(y) * w + x] && same(colour_of(word(frame, x, y)), r.ink);
  auto near_ink = [&](int x, int y) {
    for (int v = std::max(0, y - 2); v <= std::min(h - 1, y + 2); ++v)
      for (int u = std::max(0, x - 2); u <= std::min(w - 1, x + 2); ++u)
        if (ink[std::size_t(v) * w + u]) return true;
    return false;
  };
  double worst = 22;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      if (touched[std::size_t(y) * w + x] || !near_ink(x, y)) continue;
      const Color g = colour_of(word(frame, x, y));
      ++r.ground;
      const double ratio = contrast_ratio(r.ink, g);
      if (ratio < vibra::render::kLegibleContrast) ++r.faint;
      if (ratio < worst) worst = ratio, r.x = x, r.y = y, r.worst = g;
    }
  return r;
}

/// The frame of `scene` (diagram alone) at `moment` of its run (0 = first row, 1 = last).
vibra::render::Canvas frame(vibra::scenes::SceneConfig config, double moment) {
  long long steps = 0;
  auto scene = vibra::test::scene_after_pre_pass(config, steps);
  const std::vector<double> row = vibra::test::observed_row_at(*scene, config, steps, moment);
  vibra::render::Canvas canvas = vibra::render::Canvas::image(config.width, config.height);
  scene->draw(canvas, row);
  canvas.flush();
  return canvas;
}

vibra::scenes::SceneConfig configured(const std::string& scene, const std::vector<vibra::scenes::Setting>& settings) {
  vibra::scenes::SceneConfig config = vibra::scenes::load_scene(scene);
  vibra::scenes::apply_setting(config, {"layout", "fbd", "test"});
  config.width = 960, config.height = 540;
  for (const auto& s : settings) vibra::scenes::apply_setting(config, s);
  return config;
}

}  // namespace

TEST_CASE("every force arrow and its label keep 3:1 against what they sit on, in every scene at five moments",
          "[contrast][scene]") {
  // Forces cross the bodies they act on (mg from the centre of a blue box):
  // measured on the pixels, each force's colour against the pixels around
  // it. Colours no frame paints (a scene without a third force) are skipped;
  // every scene paints some force.
  struct Run {
    std::string scene;
    std::vector<vibra::scenes::Setting> settings;
  };
  std::vector<Run> runs;
  for (const std::string& name : vibra::scenes::builtin_scene_names()) runs.push_back({name, {}});
  runs.push_back({"pendulum", {{"Theta", "170", "test"}}});
  runs.push_back({"sliding_box", {{"colors.gravity", "#f0e442", "test"}}});  // a pale yellow asked for
  runs.push_back({"spring", {{"colors.background", "#101014", "test"}}});    // a dark hall's background
  for (const Run& run : runs) {
    const vibra::scenes::SceneConfig config = configured(run.scene, run.settings);
    long forces_seen = 0;
    for (double moment : {0.0, 0.25, 0.5, 0.75, 1.0}) {
      const vibra::render::Canvas canvas = frame(config, moment);
      for (vibra::render::Color vibra::scenes::SceneColors::*slot :
           {&vibra::scenes::SceneColors::gravity, &vibra::scenes::SceneColors::wire_force,
            &vibra::scenes::SceneColors::drag}) {
        vibra::scenes::SceneConfig nudged = config;
        Color& colour = nudged.colors.*slot;
        colour = {1 - colour.r, 1 - colour.g, 1 - colour.b};  // far off, so a 1% fringe changes too
        const GroundReport r = ground_of(canvas, frame(nudged, moment), config.colors.background);
        if (r.touched < 20) continue;  // no such force in this frame
        ++forces_seen;
        const Color asked = config.colors.*slot;
        INFO(run.scene << " with " << run.settings.size() << " settings at moment " << moment << ": a force asked in "
                       << asked.r << "," << asked.g << "," << asked.b << " drawn in " << r.ink.r << "," << r.ink.g
                       << "," << r.ink.b << " has " << r.faint << " of " << r.ground
                       << " ground pixels under 3:1, the worst at (" << r.x << "," << r.y << ") in " << r.worst.r
                       << "," << r.worst.g << "," << r.worst.b);
        CHECK(contrast_ratio(r.ink, config.colors.background) >= 3.0);
        // Where a casing's antialiased edge meets other ink (the coils of a
        // spring a force runs along, a thin leader line crossing a shaft,
        // two forces from one point) a few pixels blend: up to 8% of the
        // ground is left for such joins. A force on a body without its
        // casing leaves a fifth of its ground or more under 3:1.
        CHECK(r.faint <= r.ground * 8 / 100);
      }
    }
    INFO(run.scene);
    CHECK(forces_seen > 0);
  }
}
