// The table of scene keys: each key's name, help and how it sets a SceneConfig, the one place a scene key is defined.
#pragma once
#include <string>
#include <vector>

#include "core/input/parameters.hpp"
#include "scenes/config/scene_config.hpp"

namespace vibra::scenes {

/// One scene key: what `vibra render --help` shows (spec) and how its value
/// sets the configuration (apply; throws UsageError without the origin,
/// which apply_setting puts in front).
struct SceneKey {
  KeySpec spec;
  void (*apply)(SceneConfig&, const std::string& key, const std::string& value);
  /// A model key of the same name wins (the road's `speed` is the car's).
  bool yields_to_model_key = false;
};

/// Every scene key, in the order help lists them.
const std::vector<SceneKey>& scene_key_table();

/// Whether two keys set one thing: the same key, or dt and
/// steps_per_period, or T and periods, which replace each other.
bool sets_same_thing(const std::string& a, const std::string& b);

}  // namespace vibra::scenes
