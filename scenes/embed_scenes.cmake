# Writes OUTPUT: a C++ file defining builtin_scenes() from the TOML files in SCENES_DIR.
file(GLOB presets "${SCENES_DIR}/*.toml")
list(SORT presets)
set(body "")
foreach(preset ${presets})
  get_filename_component(name "${preset}" NAME_WE)
  file(READ "${preset}" text)
  string(APPEND body "      {\"${name}\", R\"vibra_toml(${text})vibra_toml\"},\n")
endforeach()
file(WRITE "${OUTPUT}.new" "// Generated from scenes/presets/*.toml by scenes/embed_scenes.cmake: do not edit.
#include \"scenes/config/builtin_scenes.hpp\"

namespace vibra::scenes {
const std::vector<std::pair<std::string, std::string>>& builtin_scenes() {
  static const std::vector<std::pair<std::string, std::string>> scenes = {
${body}  };
  return scenes;
}
}  // namespace vibra::scenes
")
file(COPY_FILE "${OUTPUT}.new" "${OUTPUT}" ONLY_IF_DIFFERENT)
