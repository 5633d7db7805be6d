// The preset scene files of scenes/presets/*.toml compiled into the program, by name.
#pragma once
#include <string>
#include <utility>
#include <vector>

namespace vibra::scenes {

/// The preset scene files of scenes/presets/*.toml, compiled into the program so
/// `vibra render pendulum` works from any directory: (name, TOML text).
const std::vector<std::pair<std::string, std::string>>& builtin_scenes();

}  // namespace vibra::scenes
