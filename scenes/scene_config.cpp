// SceneConfig: scene files, --set and flags read into one typed configuration of a render.
#include "scenes/scene_config.hpp"

#include <toml++/toml.h>

#include "scenes/scene_table.hpp"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "core/comparison.hpp"
#include "core/error.hpp"
#include "core/input_files.hpp"
#include "core/models/model.hpp"
#include "core/name_spelling.hpp"
#include "core/quoted_value.hpp"
#include "core/value_ranges.hpp"
#include "core/word_list.hpp"
#include "scenes/annotations.hpp"
#include "render/typeset/formula_parser.hpp"
#include "scenes/builtin_scenes.hpp"
#include "scenes/note.hpp"
#include "scenes/diagrams/diagram_registry.hpp"

namespace vibra::scenes {

namespace {
bool model_has_key(const std::string& model, const std::string& key) {
  for (const auto& spec : find_model(model).keys)
    if (same_name(spec.name, key)) return true;
  return false;
}

bool parse_bool(const Setting& s) {
  if (s.value == "true" || s.value == "1" || s.value == "yes") return true;
  if (s.value == "false" || s.value == "0" || s.value == "no") return false;
  throw UsageError(s.origin + ": " + s.key + "=" + s.value + " is not true or false");
}

/// A scene key's number, checked against its row of the ranges (core/value_ranges.hpp).
double parse_number(const Setting& s) {
  try {
    return in_range(s.key, evaluate_constant(s.key, s.value), s.value);
  } catch (const UsageError& e) {
    throw UsageError(s.origin + ": " + e.what());
  }
}

render::Color parse_color_setting(const Setting& s) {
  try {
    return render::parse_color(s.value);
  } catch (const std::invalid_argument& e) {
    throw UsageError(s.origin + ": " + s.key + ": " + e.what() + ", e.g. #0072b2");
  }
}

render::Color* color_slot(SceneConfig& c, const std::string& key) {
  static const std::map<std::string, render::Color SceneColors::*> slots = {
      {"colors.background", &SceneColors::background}, {"colors.bob", &SceneColors::bob},
      {"colors.wire", &SceneColors::wire},             {"colors.gravity", &SceneColors::gravity},
      {"colors.wire_force", &SceneColors::wire_force}, {"colors.drag", &SceneColors::drag}};
  auto it = slots.find(key);
  return it == slots.end() ? nullptr : &(c.colors.*(it->second));
}

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
/// Whether two keys set one thing: the same key, or dt and steps_per_period,
/// or T and periods, which replace each other.
bool sets_same_thing(const std::string& a, const std::string& b) {
  static const std::map<std::string, std::string> rivals = {
      {"dt", "steps_per_period"}, {"steps_per_period", "dt"}, {"T", "periods"}, {"periods", "T"}};
  const auto rival = rivals.find(name_key(a));
  return same_name(a, b) || (rival != rivals.end() && same_name(rival->second, b));
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

const std::vector<KeySpec>& scene_keys() {
  static const std::vector<KeySpec> keys = {
      {"model", ValueKind::choice, "pendulum", "", "model (with a diagram: any layout; others: layout plot)", {}, {}},
      {"diagram", ValueKind::choice, "", "", "drawing of the model (default: the model's own; see Diagrams below)", {}, {}},
      {"size", ValueKind::number, "1280x720", "pixels", "frame size WxH", {}, {}},
      {"fps", ValueKind::number, "30", "1/s", "frames per second of video", {}, {}},
      {"speed", ValueKind::number, "0", "time/s", "simulated time per second of video (0: one period in 2 s)", {}, {}},
      {"video_speed", ValueKind::number, "0", "time/s", "the same as speed, for models with a key speed of their own", {}, {}},
      {"frame_per_step", ValueKind::choice, "false", "", "one frame per solver step", {"true", "false"}, {}},
      {"layout", ValueKind::choice, "fbd+plot", "", "fbd, fbd+plot, plot (any model), or grid (with compare)", {"fbd", "fbd+plot", "plot", "grid"}, {}},
      {"compare", ValueKind::text, "", "", "KEY=V1,V2,...: one run per value (up to 8), drawn together", {}, {}},
      {"window", ValueKind::number, "", "time", "plot window: a time, or N periods as 8periods; none = whole run", {}, {}},
      {"window_mode", ValueKind::choice, "movement", "", "drawing, movement or jumps (the moving plot window)", {"drawing", "movement", "jumps"}, {}},
      {"panels", ValueKind::choice, "", "", "fbd+plot panels: columns, phase, energy, error, period", {}, {}},
      {"energy_bars", ValueKind::choice, "false", "", "kinetic, potential, dissipated energy beside the diagram", {"true", "false"}, {}},
      {"annotate", ValueKind::choice, "", "", "marks of the book's figures: geometry (the pendulum's i_r, i_theta, pivot, L)", {}, {}},
      {"slow", ValueKind::text, "", "", "T0-T1:FACTOR: simulated [T0, T1] FACTOR times slower (4: a quarter speed), repeatable", {}, {}},
      {"pause", ValueKind::text, "", "", "T:SECONDS: hold simulated time T for SECONDS of video, repeatable", {}, {}},
      {"drag_magnification", ValueKind::number, "5", "", "drag arrow drawn this many times longer", {}, {}},
      {"exaggerate", ValueKind::number, "0", "", "bumpy road: heights drawn this many times larger (0: automatic, 1: true scale)", {}, {}},
      {"title", ValueKind::text, "", "", "a title across the top (text; $math$ in the LaTeX subset)", {}, {}},
      {"equation", ValueKind::choice, "false", "", "the model's equation of motion under the title", {"true", "false"}, {}},
      {"notes", ValueKind::text, "", "", "callouts \"T0-T1: TEXT\" (a list; @PANEL points at a panel)", {}, {}},
      {"colors.background", ValueKind::number, "#ffffff", "", "colour #rrggbb", {}, {}},
      {"colors.bob", ValueKind::number, "#0073b3", "", "colour #rrggbb", {}, {}},
      {"colors.wire", ValueKind::number, "#1a1a1f", "", "colour #rrggbb", {}, {}},
      {"colors.gravity", ValueKind::number, "#d65e00", "", "colour #rrggbb", {}, {}},
      {"colors.wire_force", ValueKind::number, "#009e73", "", "colour #rrggbb", {}, {}},
      {"colors.drag", ValueKind::number, "#cc78a6", "", "colour #rrggbb", {}, {}},
  };
  return keys;
}

void parse_size(const std::string& text, int& width, int& height) {
  int w = 0, h = 0;
  char x = 0, extra = 0;
  std::istringstream in(text);
  if (!(in >> w >> x >> h) || (x != 'x' && x != 'X') || (in >> extra) || w < 1 || h < 1 || w > 8192 || h > 8192)
    throw UsageError("size '" + text + "' is not WxH with each side 1..8192: write e.g. 1280x720");
  width = w, height = h;
}

namespace {
/// `s` with its key spelled as the scene's or its model's keys are listed, so
/// that every comparison after it, and what is stored, sees one spelling.
Setting with_listed_key(const SceneConfig& c, const Setting& s) {
  std::vector<std::string> names = {"note"};  // --note's own name for notes
  for (const auto& spec : scene_keys()) names.push_back(spec.name);
  const Parameters model_keys = model_parameters(find_model(c.model));  // held: the loop reads its member
  for (const auto& spec : model_keys.specs()) names.push_back(spec.name);
  return {listed_spelling(s.key, names), s.value, s.origin};
}

/// The model `s` names, in its listed spelling.
std::string model_named(const Setting& s) {
  try {
    return find_model(s.value).name;
  } catch (const UsageError& e) {
    throw UsageError(s.origin + ": " + e.what());
  }
}
}  // namespace

void apply_setting(SceneConfig& c, const Setting& given) {
  const Setting s = with_listed_key(c, given);
  const std::string& k = s.key;
  if (k == "model") {
    const std::string model = model_named(s);
    if (model != c.model) c.model_settings.clear(), c.diagram.clear();  // the old model's keys do not apply
    c.model = model;
  } else if (k == "diagram") {
    std::vector<std::string> names;
    for (const auto& kind : all_diagrams()) names.push_back(kind.name);
    const std::string diagram = listed_spelling(s.value, names);
    if (std::find(names.begin(), names.end(), diagram) == names.end()) {
      const std::string near = closest_match(s.value, names);
      std::string list;
      for (const auto& n : names) list += (list.empty() ? "" : ", ") + n;
      throw UsageError(s.origin + ": unknown diagram '" + s.value + "'" +
                       (near.empty() ? "" : " (did you mean '" + near + "'?)") + ": choose one of " + list);
    }
    c.diagram = diagram;
  } else if (k == "size") {
    try {
      parse_size(s.value, c.width, c.height);
    } catch (const UsageError& e) {
      throw UsageError(s.origin + ": " + e.what());
    }
  } else if (k == "fps") {
    c.fps = parse_number(s);
  } else if (k == "video_speed" || (k == "speed" && !model_has_key(c.model, "speed"))) {
    c.speed = parse_number(s);
  } else if (k == "frame_per_step") {
    c.frame_per_step = parse_bool(s);
  } else if (k == "layout") {
    if (s.value == "fbd") c.layout = Layout::fbd;
    else if (s.value == "fbd+plot") c.layout = Layout::fbd_plot;
    else if (s.value == "plot") c.layout = Layout::plot;
    else if (s.value == "grid") c.layout = Layout::grid;
    else throw UsageError(s.origin + ": layout '" + s.value + "' is not one of fbd, fbd+plot, plot, grid");
  } else if (k == "compare") {
    try {
      parse_comparison(s.value);
    } catch (const UsageError& e) {
      throw UsageError(s.origin + ": " + e.what());
    }
    c.compare = s.value;
  } else if (k == "window") {
    c.window = s.value;
    try {
      window_width(c, 1);
    } catch (const UsageError& e) {
      throw UsageError(s.origin + ": " + e.what());
    }
  } else if (k == "window_mode") {
    try {
      c.window_mode = parse_window_mode(s.value);
    } catch (const UsageError& e) {
      throw UsageError(s.origin + ": " + e.what());
    }
  } else if (k == "panels") {
    try {
      c.panels = word_list("panels", s.value);
    } catch (const UsageError& e) {
      throw UsageError(s.origin + ": " + e.what());
    }
  } else if (k == "energy_bars") {
    c.energy_bars = parse_bool(s);
  } else if (k == "annotate") {
    try {
      c.annotate = word_list("annotate", s.value);
      for (const auto& name : c.annotate) check_annotation_name(name, "render");
    } catch (const UsageError& e) {
      throw UsageError(s.origin + ": " + e.what());
    }
  } else if (pacing_key(k)) {
    try {
      k == "slow" ? c.pacing.add_slow(s.value) : c.pacing.add_pause(s.value);
    } catch (const UsageError& e) {
      throw UsageError(s.origin + ": " + e.what());
    }
  } else if (k == "drag_magnification") {
    c.drag_magnification = parse_number(s);
  } else if (k == "exaggerate") {
    c.exaggerate = parse_number(s);
    if (c.exaggerate > 0 && c.exaggerate < 1)
      throw UsageError(s.origin + ": exaggerate=" + s.value +
                       " would shrink the motion: give 1 (true scale), more than 1, or 0 (chosen from the run)");
  } else if (k == "title") {
    try {
      (void)render::parse_rich_text(s.value);
    } catch (const UsageError& e) {
      throw UsageError(s.origin + ": title: " + e.what());
    }
    c.title = s.value;
  } else if (k == "equation") {
    c.equation = parse_bool(s);
  } else if (k == "notes" || k == "note") {
    try {
      (void)parse_note(s.value);
    } catch (const UsageError& e) {
      throw UsageError(s.origin + ": " + e.what());
    }
    c.notes.push_back(s.value);
  } else if (render::Color* slot = color_slot(c, k)) {
    *slot = parse_color_setting(s);
  } else {
    // Not a scene key: it must be one of the model's.
    Parameters p = model_parameters(find_model(c.model));
    std::vector<std::string> names;
    for (const auto& spec : p.specs()) names.push_back(spec.name);
    if (std::find(names.begin(), names.end(), k) == names.end()) {
      for (const auto& spec : scene_keys()) names.push_back(spec.name);
      const std::string near = closest_match(k, names);
      throw UsageError(s.origin + ": unknown key '" + k + "'" + (near.empty() ? "" : " (did you mean '" + near + "'?)") +
                       ": vibra render --help lists scene keys, vibra solve " + c.model + " --help the model's");
    }
    try {
      p.set(k, s.value);
    } catch (const UsageError& e) {
      throw UsageError(s.origin + ": " + e.what());
    }
    // dt replaces steps_per_period and T replaces periods (and back), so a
    // --set can override what a scene file chose the other way.
    auto same = [&](const Setting& o) { return sets_same_thing(o.key, k); };
    c.model_settings.erase(std::remove_if(c.model_settings.begin(), c.model_settings.end(), same), c.model_settings.end());
    c.model_settings.push_back(s);
  }
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

std::string builtin_scene_summary(const std::string& name) {
  for (const auto& [preset, text] : builtin_scenes()) {
    if (!same_name(preset, name)) continue;
    std::istringstream lines(text);
    std::string line;
    while (std::getline(lines, line))
      if (line.rfind("# ", 0) == 0) return line.substr(2);
  }
  return "";
}

SceneConfig load_scene(const std::string& name_or_path) {
  std::string text, file;
  for (const auto& [name, preset] : builtin_scenes())
    if (same_name(name, name_or_path)) text = preset, file = name + ".toml";
  // A model's name is a scene too (after the presets, so `pendulum` is the
  // preset): the pendulums' diagram, any model's moving plot.
  for (const auto& model : all_models()) {
    if (!file.empty() || !same_name(model.name, name_or_path)) continue;
    SceneConfig config;
    config.name = config.model = model.name;
    config.layout = default_diagram(model.name) ? Layout::fbd_plot : Layout::plot;
    return config;
  }
  if (file.empty()) {
    namespace fs = std::filesystem;
    std::error_code ec;
    if (!fs::is_regular_file(name_or_path, ec)) {
      std::string names;
      for (const auto& n : builtin_scene_names()) names += (names.empty() ? "" : ", ") + n;
      throw UsageError("no scene '" + name_or_path + "': give a scene file (.toml), a built-in scene (" + names +
                       ") or a model name (vibra solve --help lists them)");
    }
    text = read_input_file(name_or_path, "the scene file", "the scene file", kMostSettingsBytes);
    file = name_or_path;
  }
  return parse_scene(text, file);
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
