// The live page job: `vibra render SCENE -o PAGE.html --live` writes a page that re-solves and draws the scene in the browser.
#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include "scenes/config/scene_config.hpp"

namespace vibra::scenes {

struct LivePageRequest {
  std::string scene_name;  ///< a built-in scene's name: the page's WebAssembly holds those only
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
/// the page's script, style and fonts), each only when complete.
void run_live_page(const LivePageRequest&);

}  // namespace vibra::scenes
