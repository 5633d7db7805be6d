// The washing machine's arrow labels name their forces: bare formulas side by
// side ("−u" beside "sin(γt)") read as one product (docs/scenes.md).
#include <catch2/catch.hpp>
#include <cctype>
#include <string>

#include "render/draw/canvas.hpp"
#include "render/labels/drawing_record.hpp"
#include "scene_run_support.hpp"
#include "scenes/config/scene_config.hpp"
#include "scenes/scene_factory.hpp"

TEST_CASE("the washing machine's arrows are labelled by name and formula, at resonance and off it",
          "[scene][diagram][labels]") {
  for (const char* gamma : {"1", "1.1", "3"}) {
    vibra::scenes::SceneConfig config = vibra::scenes::load_scene("washing_machine");
    vibra::scenes::apply_setting(config, {"gamma", gamma, "test"});
    config.width = 640, config.height = 360;
    long long steps = 0;
    auto scene = vibra::test::scene_after_pre_pass(config, steps);
    auto runs = vibra::scenes::build_scene_runs(config);
    std::vector<double> row(runs->width());
    const long long every = std::max(1LL, steps / 8);
    for (long long step = 0; step < steps; ++step) {
      runs->row(row);
      scene->observe(row);
      if (step % every == every / 2) {
        vibra::render::Canvas canvas = vibra::render::Canvas::image(config.width, config.height);
        scene->draw(canvas, row);
        int formulas = 0;
        for (const auto& placed : scene->last_layout()->placed) {
          const std::string& markup = placed.request.markup;
          if (markup.find("<i>u</i>") == std::string::npos && markup.find("γt") == std::string::npos) continue;
          INFO("gamma = " << gamma << ", t = " << row[0] << ": label " << markup);
          ++formulas;
          // A name first: "spring −u", "damper −βu′", "drum sin(γt)".
          CHECK(std::isalpha(static_cast<unsigned char>(markup[0])));
          CHECK(markup.find(' ') != std::string::npos);
        }
        CHECK(formulas >= 2);
      }
      if (!runs->advance()) break;
    }
  }
}
