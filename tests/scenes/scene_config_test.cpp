// Tests of scene configuration: built-in scenes, model names as scenes, windows and keys.
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>

#include "cli_support.hpp"
#include "core/error.hpp"
#include "scenes/config/scene_config.hpp"

using namespace vibra;
using namespace vibra::scenes;

namespace {
std::string load_error(const std::string& text) {
  const vibra::test::ScratchDirectory dir;  // its own folder: suites may run at once
  const std::string path = dir / "vibra_scene_test.toml";
  std::ofstream(path, std::ios::binary) << text;
  try {
    load_scene(path);
  } catch (const UsageError& e) {
    return e.what();
  }
  return "no error";
}
}  // namespace

TEST_CASE("built-in scenes load with their settings", "[scene-config]") {
  SceneConfig book = load_scene("pendulum_book");
  CHECK(book.frame_per_step);
  CHECK(book.fps == 25);
  Parameters p = model_parameters_of(book);
  CHECK(p.angle("Theta") == Approx(70 * M_PI / 180));
  CHECK(p.number("alpha") == 0.4);
  CHECK(p.number("dt") == Approx(2 * M_PI / 40));
  CHECK(p.text("scheme") == "rk4");
  SceneConfig def = load_scene("pendulum");
  CHECK(def.width == 1280);
  CHECK(def.layout == Layout::fbd_plot);
}

TEST_CASE("a model name is a scene: its moving plot, or the diagram for pendulums", "[scene-config]") {
  SceneConfig undamped = load_scene("undamped");
  CHECK(undamped.model == "undamped");
  CHECK(undamped.layout == Layout::plot);
  CHECK(load_scene("physical-pendulum").layout == Layout::fbd_plot);
}

TEST_CASE("window widths in time units or periods", "[scene-config]") {
  SceneConfig c = load_scene("pendulum");
  CHECK(window_width(c, 2 * M_PI) == 0);
  apply_setting(c, {"window", "8periods", "--set"});
  CHECK(window_width(c, 2 * M_PI) == Approx(16 * M_PI));
  apply_setting(c, {"window", "12.5", "--set"});
  CHECK(window_width(c, 2 * M_PI) == 12.5);
}

TEST_CASE("settings given with --set override scene keys and model keys", "[scene-config]") {
  SceneConfig c = load_scene("pendulum");
  apply_setting(c, {"Theta", "40", "--set"});
  apply_setting(c, {"size", "640x360", "--set"});
  apply_setting(c, {"colors.bob", "#ff0000", "--set"});
  CHECK(model_parameters_of(c).angle("Theta") == Approx(40 * M_PI / 180));
  CHECK(c.width == 640);
  CHECK(c.colors.bob.r == 1.0);
}

TEST_CASE("scene file errors name the file, line and key", "[scene-config]") {
  CHECK_THAT(load_error("model = \"pendulum\"\nThta = 40\n"),
             Catch::Contains("vibra_scene_test.toml:2") && Catch::Contains("did you mean 'Theta'"));
  CHECK_THAT(load_error("fps = 30\nfps = 25\n"), Catch::Contains(":2"));
  CHECK_THAT(load_error("size = \"0x720\"\n"), Catch::Contains("1..8192"));
  CHECK_THAT(load_error("size = \"9000x720\"\n"), Catch::Contains("1..8192"));
  CHECK_THAT(load_error("fps = -3\n"), Catch::Contains("fps=-3"));
  CHECK_THAT(load_error("layout = \"sideways\"\n"), Catch::Contains("layout 'sideways'"));
  CHECK_THAT(load_error("Theta = \"abc\"\n"), Catch::Contains("Theta"));
  CHECK_THAT(load_error("[a]\n[a.b]\nc = 1\n"), Catch::Contains("nested"));
  CHECK_THAT(load_error("model = \"two-bdy\"\n"), Catch::Contains("did you mean 'two-body'"));
  CHECK_THAT(load_error("window = \"-3\"\n"), Catch::Contains("window=-3 must be a positive number"));
  CHECK_THAT(load_error("window_mode = \"sliding\"\n"), Catch::Contains("drawing, movement, jumps"));
  CHECK_THAT(load_error(std::string("\0\1\2", 3)), Catch::Contains("binary"));
  CHECK_THAT(load_error("Theta = [1, 2]\n"), Catch::Contains("must be a number, string or boolean"));
  CHECK_THAT(load_error("colors.bob = \"red\"\n"), Catch::Contains("#rrggbb"));
  CHECK_THAT(load_error(""), Catch::Contains("the scene file sets nothing"));
  CHECK_THAT(load_error("# a comment\n\n"), Catch::Contains("the scene file sets nothing"));
  // Every built-in scene is listed, whatever their number.
  CHECK_THROWS_WITH(load_scene("no_such_scene"), Catch::Contains("a built-in scene (") && Catch::Contains("pendulum, pendulum_book"));
}
