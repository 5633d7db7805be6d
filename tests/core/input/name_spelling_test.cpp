// The one spelling rule (core/input/name_spelling.hpp): a hyphen and an underscore are the same letter in the name of a scene, model, scheme, diagram or key, on the command line, in scene files and in storyboards.
#include <catch2/catch.hpp>

#include "cli_support.hpp"
#include "core/comparison.hpp"
#include "core/models/model.hpp"
#include "core/input/name_spelling.hpp"
#include "core/scheme.hpp"
#include "scenes/lecture/storyboard.hpp"
#include "scenes/config/scene_config.hpp"

using namespace vibra;

TEST_CASE("same_name reads a hyphen and an underscore as one letter, and nothing else", "[names]") {
  CHECK(same_name("elastic-pendulum", "elastic_pendulum"));
  CHECK(same_name("steps_per-period", "steps-per_period"));
  CHECK_FALSE(same_name("elastic-pendulum", "elasticpendulum"));
  CHECK_FALSE(same_name("rk4", "rk2"));
  CHECK_FALSE(same_name("Theta", "theta"));  // case is not spelling: theta is a column, Theta a key
  CHECK(listed_spelling("euler_cromer", {"rk4", "euler-cromer"}) == "euler-cromer");
  CHECK(listed_spelling("nosuch", {"rk4"}) == "nosuch");
}

TEST_CASE("models and schemes are found by either spelling and named by their listed one", "[names]") {
  CHECK(find_model("elastic_pendulum").name == "elastic-pendulum");
  CHECK(find_model("two_body").name == "two-body");
  CHECK(parse_scheme("euler_cromer_half") == Scheme::euler_cromer_half);
  CHECK(parse_scheme("crank_nicolson") == Scheme::crank_nicolson);
  CHECK_THROWS_WITH(parse_scheme("euler+cromer"), Catch::Contains("unknown scheme"));
}

TEST_CASE("a key set in either spelling is stored in the listed one, with its choice", "[names]") {
  Parameters p = model_settings("undamped", {"steps-per-period=8", "scheme=forward_euler"});
  CHECK(p.given("steps_per_period"));
  CHECK(p.text("scheme") == "forward-euler");
  CHECK(p.given_assignments() == std::vector<std::string>{"scheme=forward-euler", "steps_per_period=8"});
  CHECK(is_time_key("steps-per-period"));
}

TEST_CASE("scene keys, a scene's model and a built-in scene's name follow the rule", "[names]") {
  scenes::SceneConfig c = scenes::load_scene("spring-dashpot");
  CHECK(c.name == "spring_dashpot");
  CHECK(c.model == scenes::load_scene("spring_dashpot").model);
  scenes::apply_setting(c, {"energy-bars", "true", "--set"});
  scenes::apply_setting(c, {"colors.wire-force", "#102030", "--set"});
  CHECK(c.energy_bars);
  CHECK(c.colors.wire_force.r == Approx(0x10 / 255.0));
  scenes::apply_setting(c, {"model", "elastic_pendulum", "--set"});
  CHECK(c.model == "elastic-pendulum");
  scenes::apply_setting(c, {"steps-per-period", "12", "--set"});
  scenes::apply_setting(c, {"dt", "0.01", "--set"});  // replaces steps_per_period, whichever spelling set it
  REQUIRE(c.model_settings.size() == 1);
  CHECK(c.model_settings[0].key == "dt");
  CHECK(scenes::load_scene("bouncing_ball").model == "bouncing-ball");  // a preset and a model's name
  CHECK(scenes::load_scene("sliding_box").model == "sliding-box");
  const scenes::SceneConfig file = scenes::parse_scene("model = \"sliding_box\"\nframe-per-step = true\n", "box.toml");
  CHECK(file.model == "sliding-box");
  CHECK(file.frame_per_step);
}

TEST_CASE("a storyboard's shots name scenes and keys in either spelling", "[names]") {
  const scenes::Storyboard board = scenes::parse_storyboard(
      "[[shot]]\nscene = \"spring-dashpot\"\nenergy-bars = true\nset = { steps-per-period = 16 }\n", "story.toml");
  REQUIRE(board.shots.size() == 1);
  CHECK(board.shots[0].scene.name == "spring_dashpot");
  CHECK(board.shots[0].scene.energy_bars);
  CHECK(scenes::model_parameters_of(board.shots[0].scene).text("steps_per_period") == "16");
}

TEST_CASE("the command line takes either spelling of models, keys, experiments and long options", "[names][cli]") {
  using vibra::test::run_vibra;
  const auto same_output = [](const std::string& a, const std::string& b) {
    const auto ra = run_vibra(a), rb = run_vibra(b);
    INFO(a << " | " << b << "\n" << ra.err << rb.err);
    CHECK(ra.exit_code == 0);
    CHECK(rb.exit_code == 0);
    CHECK(ra.out == rb.out);
    CHECK(!ra.out.empty());
  };
  same_output("solve elastic_pendulum --set steps_per_period=20 --set T=1",
              "solve elastic-pendulum --set steps-per-period=20 --set T=1");
  same_output("solve undamped --set scheme=euler_cromer --set T=1", "solve undamped --set scheme=euler-cromer --set T=1");
  same_output("analyze fd_accuracy --csv --points 5", "analyze fd-accuracy --csv --points 5");
  same_output("analyze frequency --steps_per_period 10,20 --csv", "analyze frequency --steps-per-period 10,20 --csv");
}
