// The live page job: the scene checked natively, then the page and its companion folder of browser files put in place together.
#include "jobs/live_page_job.hpp"

#include <dlfcn.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include "core/error.hpp"
#include "core/input/input_files.hpp"
#include "core/input/quoted_value.hpp"
#include "jobs/render_job.hpp"
#include "render/output/output_error.hpp"
#include "render/output/place_together.hpp"
#include "render/output/temporary_file.hpp"
#include "render/page/html_page.hpp"
#include "render/page/page_parts.hpp"
#include "render/page/web_text.hpp"
#include "scenes/config/scene_keys.hpp"
#include "scenes/scene_factory.hpp"

namespace fs = std::filesystem;

namespace vibra::scenes {

namespace {

/// The files a live page carries, from the browser build's folder.
const char* const kLiveFiles[] = {"vibra_live.js",       "replay.js",           "live.js",
                                  "live.css",            "DejaVuSans.ttf",      "DejaVuSans-Oblique.ttf",
                                  "DejaVuSans-Bold.ttf", "DejaVuSans-BoldOblique.ttf"};

/// A scene file's text, for the page to set the scene up from ("" for a built-in scene).
std::string scene_text(const LivePageRequest& r) {
  if (names_builtin_scene(r.scene_name)) return "";
  return read_input_file(r.scene_name, "the scene file", "the scene file", kMostSettingsBytes);
}

/// The scene's keys the page has a control for besides the model's, as JSON
/// entries of its key table: the comparison's values, when it compares.
std::string scene_keys_json(const LivePageRequest& r) {
  if (r.scene.compare.empty()) return "[]";
  for (const SceneKey& key : scene_key_table())
    if (key.spec.name == "compare")
      return "[{\"name\":\"compare\",\"control\":\"text\",\"default\":\"-\",\"unit\":\"\",\"meaning\":" +
             render::json_string(key.spec.meaning) + "}]";
  return "[]";
}

/// The page's settings as JSON: scene (and a scene file's text), its name, model, base settings, the keys'
/// starting values, the scene's keys with controls.
std::string config_json(const LivePageRequest& r) {
  std::map<std::string, std::string> initial;  // the last setting of a key wins, as in the run
  for (const Setting& s : r.scene.model_settings) initial[s.key] = s.value;
  if (!r.scene.compare.empty()) initial["compare"] = r.scene.compare;
  std::string json = "{\"scene\":" + render::json_string(r.scene_name) + ",\"sceneText\":" +
                     render::json_string(scene_text(r)) + ",\"name\":" + render::json_string(r.scene.name) +
                     ",\"model\":" + render::json_string(r.scene.model) + ",\"base\":[";
  for (std::size_t i = 0; i < r.base.size(); ++i) json.append(i ? "," : "").append(render::json_string(r.base[i]));
  json += "],\"initial\":{";
  const char* comma = "";
  for (const auto& [key, value] : initial) {
    json.append(comma).append(render::json_string(key)).append(":").append(render::json_string(value));
    comma = ",";
  }
  return json + "},\"sceneKeys\":" + scene_keys_json(r) + "}";  // json_string writes '<' as \u003c: nothing closes the script element it sits in
}

std::string page_html(const LivePageRequest& r, const fs::path& assets, const std::string& files) {
  return render::fill_page_template(render::read_text_file(assets / "live.html.in"),
                                    {{"TITLE", render::html_escape(r.scene_name + " — live")},
                                     {"FILES", render::html_escape(render::url_path_escape(files))},
                                     {"WIDTH", std::to_string(r.scene.width)},
                                     {"HEIGHT", std::to_string(r.scene.height)},
                                     {"CONFIG", config_json(r)}});
}

/// The scene solved once natively: a setting the page could not start from
/// is refused here, with the reason the render gives, and so is a file the
/// run reads besides the scene file (the page has no files to read).
void check_scene(const LivePageRequest& r) {
  const std::unique_ptr<Trajectory> runs = build_scene_runs(r.scene);
  if (!std::isfinite(runs->info().mesh.T)) throw UsageError("a render needs a finite end time: give T or periods");
  for (const InputFile& file : input_files())
    if (file.role != "the scene file")
      throw UsageError("--live cannot take '" + quoted_value(file.path.string(), 80) + "', " + file.role +
                       ", into the page, which reads no files: give that key a value that names no file (vibra solve " +
                       r.scene.model + " --help lists them)");
}

}  // namespace

/// The folders this code may be loaded from: the running executable's
/// (vibra), and the file holding this function (Python's module; for the
/// executable, dladdr names it as it was invoked, which may not be a path).
std::vector<fs::path> loaded_from() {
  std::vector<fs::path> folders;
  std::error_code ec;
  if (const fs::path exe = fs::canonical("/proc/self/exe", ec); !ec) folders.push_back(exe.parent_path());
  Dl_info info{};
  if (dladdr(reinterpret_cast<const void*>(&loaded_from), &info) && info.dli_fname)
    if (const fs::path file = fs::canonical(info.dli_fname, ec); !ec) folders.push_back(file.parent_path());
  return folders;
}

fs::path live_assets_folder() {
  // build/vibra and build/python/vibra/_vibra*.so both reach build/live/.
  for (const fs::path& here : loaded_from())
    for (const fs::path& folder : {here / "live", here.parent_path() / "share/vibra/live", here / "../../live"})
      if (fs::exists(folder / "vibra_live.js")) return folder.lexically_normal();
  throw UsageError("--live needs the browser build (vibra_live.js), which this vibra was built without: "
                   "install the Debian package emscripten and build again with -DVIBRA_WEB=ON");
}

void run_live_page(const LivePageRequest& r) {
  if (fs::path(r.output).extension() != ".html")
    throw UsageError("--live writes a page: give -o PAGE.html (not '" + r.output + "')");
  check_scene(r);
  const fs::path assets = live_assets_folder();
  const fs::path companions = companion_folder(r.output);
  check_companion_folder(companions, r.force);
  render::TemporaryDirectory staged(companions.parent_path(), companions.filename().string());
  for (const char* name : kLiveFiles) {
    std::error_code ec;
    if (!fs::copy_file(assets / name, staged.path() / name, ec))
      throw render::OutputError("cannot copy '" + (assets / name).string() + "' into the page's folder: " + ec.message());
  }
  render::TemporaryFile page(r.output);
  render::write_text(page, page_html(r, assets, companions.filename().string()));
  staged.seal();
  check_companion_folder(companions, r.force);  // again: the user may have put a file there meanwhile
  render::place_together({{staged.path(), companions}, {page.path(), page.final_path()}});
  if (!r.quiet) std::fprintf(stderr, "vibra: wrote %s\n", one_line_message(r.output, 4096).c_str());
}

}  // namespace vibra::scenes
