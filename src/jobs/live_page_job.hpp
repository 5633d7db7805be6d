// The live page job: `vibra render SCENE -o PAGE.html --live` writes a page that re-solves and draws the scene in the browser.
#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include "scenes/config/scene_config.hpp"

namespace vibra::scenes {

struct LivePageRequest {
  /// A built-in scene's or a model's name, or a scene file: the page's
  /// WebAssembly holds the built-in ones, and the page carries a file's text.
  std::string scene_name;
  SceneConfig scene;  ///< with every setting applied (checked: the page starts from it)
  /// The settings of the command line (scene and model keys), as KEY=VALUE:
  /// the page applies them, then the keys its controls changed.
  std::vector<std::string> base;
  std::string output;  ///< PAGE.html; its companions go in PAGE_files/
  bool force = false, quiet = false;
};

/// Where the browser build's files are (vibra_live.js, the page's script
/// and style, the fonts): `live/` beside the executable in a build (and two
/// folders up from Python's module there), else `share/vibra/live/` of the
/// installation. Throws UsageError naming how to
/// build them when neither is there.
std::filesystem::path live_assets_folder();

/// Writes PAGE.html and PAGE_files/ (the WebAssembly core and scene code,
/// the page's script, style and fonts), each only when complete. A scene
/// file's text goes into the page; a scene that reads another file (a road
/// of heights) is refused naming it, as the page reads no files.
void run_live_page(const LivePageRequest&);

}  // namespace vibra::scenes
