// SceneConfig: scene files, --set and flags read into one typed configuration of a render.
#include "scenes/config/scene_config.hpp"

#include <toml++/toml.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <sstream>

#include "core/error.hpp"
#include "core/input/input_files.hpp"
#include "core/models/model.hpp"
#include "core/input/name_spelling.hpp"
#include "core/input/value_ranges.hpp"
#include "scenes/config/builtin_scenes.hpp"
#include "scenes/diagrams/diagram_registry.hpp"
#include "scenes/config/scene_keys.hpp"
#include "scenes/config/scene_table.hpp"

namespace vibra::scenes {

namespace {
std::string scalar_text(const toml::node& node) {
  if (auto s = node.value<std::string>(); s && node.is_string()) return *s;
  if (node.is_boolean()) return *node.value<bool>() ? "true" : "false";
  if (node.is_integer()) return std::to_string(*node.value<int64_t>());
  if (node.is_floating_point()) {
    char buf[32];
    return std::string(buf, std::to_chars(buf, buf + sizeof buf, *node.value<double>()).ptr);
  }
  return "";
}

bool pacing_key(const std::string& key) { return key == "slow" || key == "pause"; }

/// One item of a slow or pause list as --slow / --pause take it: a string
/// ("2-4:4", "3:1") or a table ({ from = 2, to = 4, factor = 4 }, { at = 3, seconds = 1 }).
std::string pacing_text(const std::string& key, const toml::node& item, const std::string& origin) {
  if (item.is_string()) return *item.value<std::string>();
  const toml::table* fields = item.as_table();
  const std::vector<std::string> names =
      key == "slow" ? std::vector<std::string>{"from", "to", "factor"} : std::vector<std::string>{"at", "seconds"};
  const std::string form = key == "slow" ? "\"2-4:4\" or { from = 2, to = 4, factor = 4 }" : "\"3:1\" or { at = 3, seconds = 1 }";
  if (!fields || fields->size() != names.size())
    throw UsageError(origin + ": each " + key + " is " + form);
  std::string text;
  for (std::size_t i = 0; i < names.size(); ++i) {
    const toml::node* field = fields->get(names[i]);
    if (!field || !(field->is_integer() || field->is_floating_point())) throw UsageError(origin + ": each " + key + " is " + form);
    text += (i == 0 ? "" : key == "slow" && i == 1 ? "-" : ":") + scalar_text(*field);
  }
  return text;
}

void collect(const toml::table& table, const std::string& prefix, const std::string& file, const std::string& where,
             const std::vector<std::string>& skip, std::vector<Setting>& out) {
  for (auto&& [key, node] : table) {
    const std::string name = prefix + std::string(key.str());
    if (std::find(skip.begin(), skip.end(), name) != skip.end()) continue;
    const std::string origin =
        file + ":" + std::to_string(node.source().begin.line) + (where.empty() ? "" : ": " + where + ", " + name);
    if (const toml::table* inner = node.as_table()) {
      if (!prefix.empty()) throw UsageError(origin + ": table '" + name + "' is nested too deeply (one level, e.g. [colors])");
      collect(*inner, name + ".", file, where, {}, out);
      continue;
    }
    if (const toml::array* list = node.as_array(); list && pacing_key(name)) {
      for (const toml::node& item : *list) out.push_back({name, pacing_text(name, item, origin), origin});
      continue;
    }
    if (const toml::array* list = node.as_array(); list && name == "notes") {
      // notes = ["2-4: ...", ...]: one setting per note.
      for (const toml::node& item : *list) {
        if (!item.is_string())
          throw UsageError(origin + ": notes must be a list of strings, e.g. notes = [\"2-4: drag takes energy out\"]");
        out.push_back({name, *item.value<std::string>(), origin});
      }
      continue;
    }
    std::string text = scalar_text(node);
    if (text.empty() && node.is_string())  // a string, but empty: no value, never the default
      throw UsageError(origin + ": " + name + " = \"\" is empty: give it a value, or delete the line for the default");
    if (text.empty()) throw UsageError(origin + ": " + name + " must be a number, string or boolean");
    out.push_back({name, text, origin});
  }
}
}  // namespace

namespace {
void refuse_long_keys_in(const toml::node& node, const std::string& file, int depth) {
  if (depth > 8) return;  // deeper than any key vibra reads: table_settings refuses it
  if (const toml::array* list = node.as_array())
    for (const toml::node& item : *list) refuse_long_keys_in(item, file, depth + 1);
  const toml::table* table = node.as_table();
  if (!table) return;
  for (auto&& [key, value] : *table) {
    if (key.str().size() > kLongestKey)
      throw UsageError(file + ":" + std::to_string(key.source().begin.line) + ": a key of " +
                       std::to_string(key.str().size()) + " characters: keys are at most " +
                       std::to_string(kLongestKey) + " (vibra render --help lists the scene keys)");
    refuse_long_keys_in(value, file, depth + 1);
  }
}
}  // namespace

void refuse_long_keys(const toml::table& table, const std::string& file) { refuse_long_keys_in(table, file, 0); }

std::vector<Setting> table_settings(const toml::table& table, const std::string& file, const std::string& where,
                                    const std::vector<std::string>& skip) {
  std::vector<Setting> settings;
  collect(table, "", file, where, skip, settings);
  return settings;
}

void parse_size(const std::string& text, int& width, int& height) {
  int w = 0, h = 0;
  char x = 0, extra = 0;
  std::istringstream in(text);
  if (!(in >> w >> x >> h) || (x != 'x' && x != 'X') || (in >> extra) || w < 1 || h < 1 || w > 8192 || h > 8192)
    throw UsageError("size '" + text + "' is not WxH with each side 1..8192: write e.g. 1280x720");
  width = w, height = h;
}

double window_width(const SceneConfig& c, double period) {
  if (c.window.empty() || c.window == "none" || c.window == "0") return 0;
  std::string text = c.window;
  double unit = 1;
  const std::string suffix = "periods";
  if (text.size() > suffix.size() && text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0) {
    text.resize(text.size() - suffix.size());
    if (!(period > 0)) throw UsageError("window=" + c.window + ": this model has no period; give the window in time units");
    unit = period;
  }
  const double w = in_range("window", evaluate_constant("window", text), c.window) * unit;
  if (!(w > 0) || !std::isfinite(w)) throw UsageError("window=" + c.window + " must be positive, e.g. 10 or 8periods");
  return w;
}

Parameters model_parameters_of(const SceneConfig& c) {
  Parameters p = model_parameters(find_model(c.model));
  for (const auto& s : c.model_settings) p.set(s.key, s.value);
  return p;
}

Parameters comparison_base_of(const SceneConfig& c, const std::string& key) {
  SceneConfig base = c;
  auto compared = [&](const Setting& s) { return sets_same_thing(s.key, key); };
  for (const Setting& s : c.model_settings)
    if (compared(s) && s.origin == "--set")
      throw UsageError(s.key + " is given both in --set and in --compare: drop --set " + s.key);
  std::erase_if(base.model_settings, compared);
  return model_parameters_of(base);
}

std::vector<std::string> builtin_scene_names() {
  std::vector<std::string> names;
  for (const auto& [name, text] : builtin_scenes()) names.push_back(name);
  return names;
}

namespace {
/// The built-in preset (its name and TOML text) spelled `name`, if any.
const std::pair<std::string, std::string>* builtin_preset(const std::string& name) {
  for (const auto& preset : builtin_scenes())
    if (same_name(preset.first, name)) return &preset;
  return nullptr;
}

/// The model spelled `name`, if any: a model's name is a scene too.
const ModelDefinition* scene_model(const std::string& name) {
  for (const auto& model : all_models())
    if (same_name(model.name, name)) return &model;
  return nullptr;
}
}  // namespace

std::string builtin_scene_summary(const std::string& name) {
  const auto* preset = builtin_preset(name);
  if (!preset) return "";
  std::istringstream lines(preset->second);
  std::string line;
  while (std::getline(lines, line))
    if (line.rfind("# ", 0) == 0) return line.substr(2);
  return "";
}

bool names_builtin_scene(const std::string& name_or_path) {
  return builtin_preset(name_or_path) || scene_model(name_or_path);
}

SceneConfig load_scene(const std::string& name_or_path) {
  if (const auto* preset = builtin_preset(name_or_path)) return parse_scene(preset->second, preset->first + ".toml");
  // A model's name after the presets (so `pendulum` is the preset): the
  // pendulums' diagram, any model's moving plot.
  if (const ModelDefinition* model = scene_model(name_or_path)) {
    SceneConfig config;
    config.name = config.model = model->name;
    config.layout = default_diagram(model->name) ? Layout::fbd_plot : Layout::plot;
    return config;
  }
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::is_regular_file(name_or_path, ec)) {
    std::string names;
    for (const auto& n : builtin_scene_names()) names += (names.empty() ? "" : ", ") + n;
    throw UsageError("no scene '" + name_or_path + "': give a scene file (.toml), a built-in scene (" + names +
                     ") or a model name (vibra solve --help lists them)");
  }
  return parse_scene(read_input_file(name_or_path, "the scene file", "the scene file", kMostSettingsBytes), name_or_path);
}

SceneConfig parse_scene(const std::string& text, const std::string& file) {
  if (text.find('\0') != std::string::npos) throw UsageError(file + ": is a binary file, not a TOML scene file");
  toml::table table;
  try {
    table = toml::parse(text, file);
  } catch (const toml::parse_error& e) {
    throw UsageError(file + ":" + std::to_string(e.source().begin.line) + ": " + std::string(e.description()) +
                     " (scene files are TOML: key = value)");
  }
  refuse_long_keys(table, file);
  if (table.empty())
    throw UsageError(file + ": the scene file sets nothing: give at least model = \"pendulum\" (vibra render --help lists the keys)");
  const std::vector<Setting> settings = table_settings(table, file);
  SceneConfig config;
  config.name = std::filesystem::path(file).stem().string();
  // The model comes first: the other keys are checked against it.
  for (const auto& s : settings)
    if (s.key == "model") apply_setting(config, s);
  for (const auto& s : settings)
    if (s.key != "model") apply_setting(config, s);
  return config;
}

}  // namespace vibra::scenes
