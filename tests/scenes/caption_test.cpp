// A run's caption fits its area: on one line when it can, else on two
// (then smaller), cut short with "…" only when nothing else fits; in a scene
// its ink stays inside the diagram's part of the frame.
#include <catch2/catch.hpp>
#include <string>

#include "core/models/model.hpp"
#include "render/draw/caption.hpp"
#include "scenes/overlays/run_caption.hpp"
#include "scenes/scene_factory.hpp"
#include "scenes/system_scene.hpp"
#include "test_support.hpp"

using namespace vibra;

namespace {
std::string joined(const std::vector<std::string>& lines) {
  std::string out;
  for (const auto& l : lines) out += (out.empty() ? "" : render::kCaptionSeparator) + l;
  return out;
}

/// Columns [x0, x1) of pixels that differ between two canvases of one size.
std::pair<int, int> differing_columns(const render::Canvas& a, const render::Canvas& b) {
  a.flush(), b.flush();
  int x0 = a.width(), x1 = 0;
  for (int y = 0; y < a.height(); ++y) {
    const auto* pa = reinterpret_cast<const std::uint32_t*>(a.data() + y * a.stride());
    const auto* pb = reinterpret_cast<const std::uint32_t*>(b.data() + y * b.stride());
    for (int x = 0; x < a.width(); ++x)
      if (pa[x] != pb[x]) x0 = std::min(x0, x), x1 = std::max(x1, x + 1);
  }
  return {x0, x1};
}

/// The last row of a spring-dashpot scene at w x h with `settings`, drawn with
/// and without its caption; the scene with the caption is returned too.
struct Drawn {
  render::Canvas with, without;
  std::unique_ptr<scenes::Scene> scene;
};
Drawn draw_spring_dashpot(int w, int h, const std::vector<std::pair<std::string, std::string>>& settings) {
  scenes::SceneConfig config = scenes::load_scene("spring_dashpot");
  config.width = w, config.height = h;
  for (const auto& [k, v] : settings) scenes::apply_setting(config, {k, v, "test"});
  const Parameters p = scenes::model_parameters_of(config);
  auto run = find_model(config.model).build(p);
  const auto rows = test::rows(*run);
  const std::string caption = scenes::run_caption(config.model, p, run->info().mesh);
  Drawn d{render::Canvas::image(w, h), render::Canvas::image(w, h), nullptr};
  for (int with = 0; with < 2; ++with) {
    auto scene = scenes::make_scene(config, run->info(), with ? caption : "");
    for (const auto& row : rows) scene->record(row);
    scene->draw(with ? d.with : d.without, rows.back());
    if (with) d.scene = std::move(scene);
  }
  return d;
}
}  // namespace

TEST_CASE("caption: one line when it fits, else two lines broken between facts, every fact kept", "[render][caption]") {
  render::Canvas canvas = render::Canvas::image(640, 360);
  const std::string text = "vibration · centered · Δ<i>t</i> = 0.1047 · m=1 · k=1 · b=0.15 · damping=linear";
  const render::TextStyle style{15};
  const double wide = render::text_size(canvas, text, style).x() + 1;
  const render::Caption one = render::fit_caption(canvas, text, wide, style, 2);
  CHECK(one.lines == std::vector<std::string>{text});
  CHECK(one.style.size == 15);

  const render::Caption two = render::fit_caption(canvas, text, 0.6 * wide, style, 2);
  REQUIRE(two.lines.size() == 2);
  CHECK(joined(two.lines) == text);
  for (const auto& line : two.lines) CHECK(render::text_size(canvas, line, two.style).x() <= 0.6 * wide);
  CHECK(two.height() == Approx(2 * two.line_height));
}

TEST_CASE("caption: too long for two lines, it shrinks to 80% and then ends in an ellipsis inside its width",
          "[render][caption]") {
  render::Canvas canvas = render::Canvas::image(640, 360);
  std::string text = "vibration · centered";
  for (int i = 0; i < 30; ++i) text += " · key" + std::to_string(i) + "=" + std::to_string(i * 1.5);
  const render::Caption c = render::fit_caption(canvas, text, 250, {15}, 2);
  REQUIRE(c.lines.size() == 2);
  CHECK(c.style.size == Approx(12));
  // Drawn, its ink stays left of the width given.
  canvas.clear(render::palette::paper);
  render::Canvas blank = render::Canvas::image(640, 360);
  blank.clear(render::palette::paper);
  render::draw_caption(canvas, {10, 340}, c);
  const auto [x0, x1] = differing_columns(canvas, blank);
  CHECK(x0 >= 10);
  CHECK(x1 <= 10 + 250);
  CHECK(x1 > 10 + 200);  // the last line runs up to the ellipsis
}

TEST_CASE("caption: a long run caption stays inside the diagram's half of the frame, every fact kept",
          "[render][caption]") {
  const std::vector<std::pair<std::string, std::string>> settings = {
      {"b", "0.125"}, {"F", "0.3*cos(1.2*t) + 0.05*sin(3*t)"}, {"I", "1.25"}, {"V", "-0.5"}};
  for (auto [w, h] : {std::pair{640, 360}, std::pair{1920, 1080}}) {
    INFO(w << "x" << h);
    Drawn d = draw_spring_dashpot(w, h, settings);
    auto& scene = dynamic_cast<scenes::SystemScene&>(*d.scene);
    const auto [x0, x1] = differing_columns(d.with, d.without);
    REQUIRE(x1 > x0);  // the caption was drawn
    CHECK(x1 <= scene.diagram_area().x + scene.diagram_area().w);
    REQUIRE(scene.caption());
    CHECK(joined(scene.caption()->lines).find("<i>V</i> = -0.5") != std::string::npos);  // nothing cut off
    CHECK(scene.caption()->lines.size() >= 2);  // too long for one line in the diagram's part
    CHECK(scene.caption()->lines.size() <= 3);
  }
}
