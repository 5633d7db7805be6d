// The diagram registry: each model's default diagram, a diagram named for another model, and an unknown name, each answered by name.
#include <catch2/catch.hpp>
#include <string>

#include "core/error.hpp"
#include "scenes/config/scene_config.hpp"
#include "scenes/diagrams/diagram_registry.hpp"

using namespace vibra;
using namespace vibra::scenes;

namespace {
std::string chosen(const std::string& model, const std::string& diagram) {
  SceneConfig config;
  config.model = model, config.diagram = diagram;
  try {
    return diagram_for(config).name;
  } catch (const UsageError& e) {
    return e.what();
  }
}
}  // namespace

TEST_CASE("each model with a diagram gets its own by default, and a model without one none", "[diagram_registry]") {
  const std::pair<const char*, const char*> kDefaults[] = {
      {"pendulum", "pendulum"},         {"vibration", "oscillator"},       {"sliding-box", "sliding_box"},
      {"bumpy-road", "bumpy_road"},     {"bouncing-ball", "bouncing_ball"}, {"rlc", "rlc"},
      {"elastic-pendulum", "elastic_pendulum"}, {"two-body", "orbit"}, {"resonance", "washing_machine"}};
  for (const auto& [model, diagram] : kDefaults) {
    INFO(model);
    CHECK(chosen(model, "") == diagram);
    REQUIRE(default_diagram(model));
    CHECK(default_diagram(model)->name == diagram);
  }
  CHECK(default_diagram("no-such-model") == nullptr);
}

TEST_CASE("a diagram is refused for a model it does not draw, and an unknown one with the nearest name", "[diagram_registry]") {
  CHECK(chosen("resonance", "washing_machine") == "washing_machine");
  CHECK(chosen("pendulum", "rlc") ==
        "diagram rlc draws model rlc, not pendulum: set model accordingly or choose another diagram");
  const std::string unknown = chosen("pendulum", "pendulm");
  CHECK(unknown.rfind("unknown diagram 'pendulm' (did you mean 'pendulum'?): choose one of pendulum, oscillator, ", 0) == 0);
  const std::string none = chosen("undamped", "");
  CHECK(none.rfind("model undamped has no free-body diagram: use --layout plot (diagrams: pendulum, ", 0) == 0);
}
