// A built-in scene's diagram after its pre-pass over a whole run, for tests that inspect what it draws at each row.
#pragma once
#include <catch2/catch.hpp>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "core/models/model.hpp"
#include "scenes/diagrams/diagram_registry.hpp"
#include "scenes/config/scene_config.hpp"
#include "test_support.hpp"

namespace vibra::test {

struct RecordedDiagram {
  scenes::SceneConfig config;
  std::unique_ptr<scenes::Diagram> diagram;
  std::vector<std::vector<double>> rows;
  scenes::WorldBox world;
};

/// The diagram of `scene` with `settings` applied (model or scene keys), its
/// pre-pass over every solver row done, and those rows.
inline RecordedDiagram record_diagram(const std::string& scene,
                                      const std::vector<std::pair<std::string, std::string>>& settings = {}) {
  RecordedDiagram r{scenes::load_scene(scene), nullptr, {}, {}};
  for (const auto& [k, v] : settings) scenes::apply_setting(r.config, {k, v, "test"});
  const Parameters p = scenes::model_parameters_of(r.config);
  auto run = find_model(r.config.model).build(p);
  r.diagram = scenes::diagram_for(r.config).make({r.config, p, run->info()});
  r.rows = rows(*run);
  r.world.setEmpty();
  for (const auto& row : r.rows) r.diagram->record(row, r.world);
  r.diagram->finish_recording(r.world);
  return r;
}

/// The diagram as the type it is drawn by.
template <class T>
T& diagram_as(const RecordedDiagram& r) {
  auto* d = dynamic_cast<T*>(r.diagram.get());
  REQUIRE(d != nullptr);
  return *d;
}

}  // namespace vibra::test
