// A pendulum's support is drawn where no bob of the run ever is: a ceiling
// while the motion stays below it, a bearing block when it goes over the top
// or is flung above its pivot; and its link is a strut when it pushes
// (docs/drawing.md).
#include <catch2/catch.hpp>
#include <cmath>

#include "core/models/model.hpp"
#include "scenes/diagrams/diagram_registry.hpp"
#include "scenes/diagrams/elastic_pendulum_diagram.hpp"
#include "scenes/diagrams/pendulum/pendulum_diagram.hpp"
#include "scenes/scene_factory.hpp"
#include "test_support.hpp"

using namespace vibra;
using namespace vibra::scenes;

namespace {
struct Run {
  std::unique_ptr<Diagram> diagram;
  std::vector<std::vector<double>> rows;
};

/// A built-in scene's diagram after its pre-pass over the run.
Run recorded(const std::string& scene, const std::vector<std::pair<std::string, std::string>>& settings) {
  SceneConfig config = load_scene(scene);
  for (const auto& [k, v] : settings) apply_setting(config, {k, v, "test"});
  const Parameters p = model_parameters_of(config);
  auto trajectory = find_model(config.model).build(p);
  Run run{diagram_for(config).make({config, p, trajectory->info()}), vibra::test::rows(*trajectory)};
  WorldBox world;
  world.setEmpty();
  for (const auto& row : run.rows) run.diagram->record(row, world);
  run.diagram->finish_recording(world);
  return run;
}

/// Whether a disc of radius r at c overlaps the box.
bool overlaps(const WorldBox& box, const Point& c, double r) { return box.exteriorDistance(c) < r; }
}  // namespace

TEST_CASE("the rigid pendulum's support: no bob of the run inside its hatched region", "[scene][pendulum][support]") {
  const double r = PendulumDiagramOptions{}.bob_radius;
  const std::vector<std::pair<std::vector<std::pair<std::string, std::string>>, bool>> runs = {
      {{{"Theta", "60"}}, true},
      {{{"Theta", "100"}}, false},
      {{{"Theta", "170"}, {"alpha", "0"}}, false},
      {{{"Theta", "179"}}, false},
      {{{"Theta", "10"}, {"Omega", "150"}}, false},  // over the top: Omega^2/2 > 2 in rad
  };
  for (const auto& [settings, ceiling] : runs) {
    INFO(settings.front().first << " = " << settings.front().second);
    const Run run = recorded("pendulum", settings);
    const auto& support = dynamic_cast<const PendulumDiagram&>(*run.diagram).support();
    CHECK(support.is_ceiling() == ceiling);
    const WorldBox hatched = support.region();
    for (const auto& row : run.rows) CHECK_FALSE(overlaps(hatched, Point(std::sin(row[1]), -std::cos(row[1])), r));
  }
}

TEST_CASE("the elastic pendulum's support: no bob of the run inside its hatched region", "[scene][pendulum][support]") {
  const std::vector<std::pair<std::vector<std::pair<std::string, std::string>>, bool>> runs = {
      {{}, true},
      {{{"beta", "0.8"}, {"Theta", "90"}, {"eps", "0.2"}}, false},  // flung over its pivot
      {{{"Theta", "150"}}, false},
  };
  for (const auto& [settings, ceiling] : runs) {
    INFO(settings.size() << " settings");
    const Run run = recorded("elastic_pendulum", settings);
    const auto& support = dynamic_cast<const ElasticPendulumDiagram&>(*run.diagram).support();
    CHECK(support.is_ceiling() == ceiling);
    const WorldBox hatched = support.region();
    for (const auto& row : run.rows) CHECK_FALSE(overlaps(hatched, Point(row[1], row[2]), ElasticPendulumDiagram::kBob));
  }
}

TEST_CASE("a rigid pendulum whose link pushes (S < 0) is drawn and named as a strut, one that only pulls as a wire",
          "[scene][pendulum][support]") {
  // Released at rest, S = omega^2 + cos(Theta) = cos(Theta): negative above
  // the horizontal (170 degrees), and the link pushes the bob out; at 60
  // degrees, and at every later moment of that swing, it pulls.
  auto key_names = [](const Diagram& d) {
    std::string names;
    const auto key = d.force_key();  // held: a range-for over key->names of a temporary dangles
    for (const auto& n : key->names) names += n.name + "; ";
    return names;
  };
  const Run pushed = recorded("pendulum", {{"Theta", "170"}});
  const Run pulled = recorded("pendulum", {{"Theta", "60"}});
  CHECK(pushed.rows.front()[3] == Approx(std::cos(170 * M_PI / 180)));
  CHECK(dynamic_cast<const PendulumDiagram&>(*pushed.diagram).strut());
  CHECK_FALSE(dynamic_cast<const PendulumDiagram&>(*pulled.diagram).strut());
  CHECK_THAT(key_names(*pushed.diagram), Catch::Contains("strut"));
  CHECK_THAT(key_names(*pulled.diagram), !Catch::Contains("strut") && Catch::Contains("wire"));
  // The S panel's title names a pushing rod only for a swing that rises
  // above the horizontal (released within 90 degrees, S = cos(theta) + omega^2 > 0).
  CHECK_THAT(pushed.diagram->panels()[1].label, Catch::Contains("a rod, pushing"));
  CHECK_THAT(pulled.diagram->panels()[1].label, !Catch::Contains("rod") && Catch::Contains("wire force"));
}
