// The table of scene keys and apply_setting, which looks a key up in it (or else in the scene's model).
#include "scenes/config/scene_keys.hpp"

#include <algorithm>
#include <map>

#include "core/comparison.hpp"
#include "core/error.hpp"
#include "core/models/model.hpp"
#include "core/input/name_spelling.hpp"
#include "core/input/value_ranges.hpp"
#include "core/input/word_list.hpp"
#include "render/typeset/formula_parser.hpp"
#include "scenes/overlays/annotations.hpp"
#include "scenes/diagrams/diagram_registry.hpp"
#include "scenes/overlays/note.hpp"
#include "scenes/panels/series_panel.hpp"

namespace vibra::scenes {

namespace {
bool parse_bool(const std::string& key, const std::string& value) {
  if (value == "true" || value == "1" || value == "yes") return true;
  if (value == "false" || value == "0" || value == "no") return false;
  throw UsageError(key + "=" + value + " is not true or false");
}

/// A scene key's number, checked against its row of the ranges (core/input/value_ranges.hpp).
double parse_number(const std::string& key, const std::string& value) {
  return in_range(key, evaluate_constant(key, value), value);
}

void set_model(SceneConfig& c, const std::string&, const std::string& value) {
  const std::string model = find_model(value).name;
  if (model != c.model) c.model_settings.clear(), c.diagram.clear();  // the old model's keys do not apply
  c.model = model;
}

void set_diagram(SceneConfig& c, const std::string&, const std::string& value) {
  std::vector<std::string> names;
  for (const auto& kind : all_diagrams()) names.push_back(kind.name);
  const std::string diagram = listed_spelling(value, names);
  if (std::find(names.begin(), names.end(), diagram) == names.end()) {
    const std::string near = closest_match(value, names);
    std::string list;
    for (const auto& n : names) list += (list.empty() ? "" : ", ") + n;
    throw UsageError("unknown diagram '" + value + "'" + (near.empty() ? "" : " (did you mean '" + near + "'?)") +
                     ": choose one of " + list);
  }
  c.diagram = diagram;
}

void set_layout(SceneConfig& c, const std::string&, const std::string& value) {
  static const std::map<std::string, Layout> layouts = {
      {"fbd", Layout::fbd}, {"fbd+plot", Layout::fbd_plot}, {"plot", Layout::plot}, {"grid", Layout::grid}};
  const auto found = layouts.find(value);
  if (found == layouts.end()) throw UsageError("layout '" + value + "' is not one of fbd, fbd+plot, plot, grid");
  c.layout = found->second;
}

void set_window(SceneConfig& c, const std::string&, const std::string& value) {
  c.window = value;
  window_width(c, 1);  // checks it
}

void set_annotate(SceneConfig& c, const std::string&, const std::string& value) {
  c.annotate = word_list("annotate", value);
  for (const auto& name : c.annotate) check_annotation_name(name, "render");
}

void set_exaggerate(SceneConfig& c, const std::string& key, const std::string& value) {
  c.exaggerate = parse_number(key, value);
  if (c.exaggerate > 0 && c.exaggerate < 1)
    throw UsageError("exaggerate=" + value + " would shrink the motion: give 1 (true scale), more than 1, or 0 (chosen from the run)");
}

void set_title(SceneConfig& c, const std::string&, const std::string& value) {
  try {
    (void)render::parse_rich_text(value);
  } catch (const UsageError& e) {
    throw UsageError(std::string("title: ") + e.what());
  }
  c.title = value;
}

/// A colour key's setter: the table holds one per member of SceneColors.
template <render::Color SceneColors::*member>
void set_color(SceneConfig& c, const std::string& key, const std::string& value) {
  try {
    c.colors.*member = render::parse_color(value);
  } catch (const std::invalid_argument& e) {
    throw UsageError(key + ": " + e.what() + ", e.g. #0072b2");
  }
}

/// A number key's setter, for the member it names.
template <auto member>
void set_number(SceneConfig& c, const std::string& key, const std::string& value) {
  c.*member = parse_number(key, value);
}

/// A true/false key's setter, for the member it names.
template <bool SceneConfig::*member>
void set_bool(SceneConfig& c, const std::string& key, const std::string& value) {
  c.*member = parse_bool(key, value);
}

SceneKey color_key(const char* name, const char* default_value,
                   void (*apply)(SceneConfig&, const std::string&, const std::string&)) {
  return {{name, ValueKind::number, default_value, "", "colour #rrggbb", {}, {}}, apply};
}
}  // namespace

const std::vector<SceneKey>& scene_key_table() {
  using K = ValueKind;
  static const std::vector<SceneKey> table = {
      {{"model", K::choice, "pendulum", "", "model (with a diagram: any layout; others: layout plot)", {}, {}}, set_model},
      {{"diagram", K::choice, "", "", "drawing of the model (default: the model's own; see Diagrams below)", {}, {}}, set_diagram},
      {{"size", K::number, "1280x720", "pixels", "frame size WxH", {}, {}},
       [](SceneConfig& c, const std::string&, const std::string& v) { parse_size(v, c.width, c.height); }},
      {{"fps", K::number, "30", "1/s", "frames per second of video", {}, {}}, set_number<&SceneConfig::fps>},
      {{"speed", K::number, "0", "time/s", "simulated time per second of video (0: one period in 2 s)", {}, {}},
       set_number<&SceneConfig::speed>, true},
      {{"video_speed", K::number, "0", "time/s", "the same as speed, for models with a key speed of their own", {}, {}},
       set_number<&SceneConfig::speed>},
      {{"frame_per_step", K::choice, "false", "", "one frame per solver step", {"true", "false"}, {}},
       set_bool<&SceneConfig::frame_per_step>},
      {{"layout", K::choice, "fbd+plot", "", "fbd, fbd+plot, plot (any model), or grid (with compare)", {"fbd", "fbd+plot", "plot", "grid"}, {}},
       set_layout},
      {{"compare", K::text, "", "", "KEY=V1,V2,...: one run per value (up to 8), drawn together", {}, {}},
       [](SceneConfig& c, const std::string&, const std::string& v) { parse_comparison(v), c.compare = v; }},
      {{"window", K::number, "", "time", "plot window: a time, or N periods as 8periods; none = whole run", {}, {}}, set_window},
      {{"window_mode", K::choice, "movement", "", "drawing, movement or jumps (the moving plot window)", {"drawing", "movement", "jumps"}, {}},
       [](SceneConfig& c, const std::string&, const std::string& v) { c.window_mode = parse_window_mode(v); }},
      {{"panels", K::choice, "", "", "fbd+plot panels: columns, phase, energy, error, period", {}, {}},
       [](SceneConfig& c, const std::string&, const std::string& v) { c.panels = word_list("panels", v); }},
      {{"energy_bars", K::choice, "false", "", "kinetic, potential, dissipated energy beside the diagram", {"true", "false"}, {}},
       set_bool<&SceneConfig::energy_bars>},
      {{"annotate", K::choice, "", "", "marks of the book's figures: geometry (the pendulum's i_r, i_theta, pivot, L)", {}, {}},
       set_annotate},
      {{"slow", K::text, "", "", "T0-T1:FACTOR: simulated [T0, T1] FACTOR times slower (4: a quarter speed), repeatable", {}, {}},
       [](SceneConfig& c, const std::string&, const std::string& v) { c.pacing.add_slow(v); }},
      {{"pause", K::text, "", "", "T:SECONDS: hold simulated time T for SECONDS of video, repeatable", {}, {}},
       [](SceneConfig& c, const std::string&, const std::string& v) { c.pacing.add_pause(v); }},
      {{"drag_magnification", K::number, "5", "", "drag arrow drawn this many times longer", {}, {}},
       set_number<&SceneConfig::drag_magnification>},
      {{"exaggerate", K::number, "0", "", "bumpy road: heights drawn this many times larger (0: automatic, 1: true scale)", {}, {}},
       set_exaggerate},
      {{"title", K::text, "", "", "a title across the top (text; $math$ in the LaTeX subset)", {}, {}}, set_title},
      {{"equation", K::choice, "false", "", "the model's equation of motion under the title", {"true", "false"}, {}},
       set_bool<&SceneConfig::equation>},
      {{"notes", K::text, "", "", "callouts \"T0-T1: TEXT\" (a list; @PANEL points at a panel)", {}, {}},
       [](SceneConfig& c, const std::string&, const std::string& v) { (void)parse_note(v), c.notes.push_back(v); }},
      color_key("colors.background", "#ffffff", set_color<&SceneColors::background>),
      color_key("colors.bob", "#0073b3", set_color<&SceneColors::bob>),
      color_key("colors.wire", "#1a1a1f", set_color<&SceneColors::wire>),
      color_key("colors.gravity", "#d65e00", set_color<&SceneColors::gravity>),
      color_key("colors.wire_force", "#009e73", set_color<&SceneColors::wire_force>),
      color_key("colors.drag", "#cc78a6", set_color<&SceneColors::drag>),
  };
  return table;
}

const std::vector<KeySpec>& scene_keys() {
  static const std::vector<KeySpec> specs = [] {
    std::vector<KeySpec> out;
    for (const SceneKey& key : scene_key_table()) out.push_back(key.spec);
    return out;
  }();
  return specs;
}

bool sets_same_thing(const std::string& a, const std::string& b) {
  static const std::map<std::string, std::string> rivals = {
      {"dt", "steps_per_period"}, {"steps_per_period", "dt"}, {"T", "periods"}, {"periods", "T"}};
  const auto rival = rivals.find(name_key(a));
  return same_name(a, b) || (rival != rivals.end() && same_name(rival->second, b));
}

namespace {
/// --note's own name for the scene key notes.
constexpr const char* kNoteAlias = "note";

/// `s` with its key spelled as the scene's or its model's keys are listed, so
/// that every comparison after it, and what is stored, sees one spelling.
Setting with_listed_key(const SceneConfig& c, const Setting& s) {
  std::vector<std::string> names = {kNoteAlias};
  for (const auto& spec : scene_keys()) names.push_back(spec.name);
  const Parameters model_keys = model_parameters(find_model(c.model));  // held: the loop reads its member
  for (const auto& spec : model_keys.specs()) names.push_back(spec.name);
  const std::string key = listed_spelling(s.key, names);
  return {key == kNoteAlias ? "notes" : key, s.value, s.origin};
}

/// The scene key row named `key`, unless the key is none or yields to the model's.
const SceneKey* scene_key_named(const SceneConfig& c, const std::string& key) {
  for (const SceneKey& row : scene_key_table()) {
    if (row.spec.name != key) continue;
    if (row.yields_to_model_key)
      for (const auto& spec : find_model(c.model).keys)
        if (same_name(spec.name, key)) return nullptr;
    return &row;
  }
  return nullptr;
}

/// A key of the scene's model: checked, then stored in place of any setting of the same thing.
void apply_model_setting(SceneConfig& c, const Setting& s) {
  Parameters p = model_parameters(find_model(c.model));
  std::vector<std::string> names;
  for (const auto& spec : p.specs()) names.push_back(spec.name);
  if (std::find(names.begin(), names.end(), s.key) == names.end()) {
    for (const auto& spec : scene_keys()) names.push_back(spec.name);
    const std::string near = closest_match(s.key, names);
    throw UsageError("unknown key '" + s.key + "'" + (near.empty() ? "" : " (did you mean '" + near + "'?)") +
                     ": vibra render --help lists scene keys, vibra solve " + c.model + " --help the model's");
  }
  p.set(s.key, s.value);
  // dt replaces steps_per_period and T replaces periods (and back), so a
  // --set can override what a scene file chose the other way.
  std::erase_if(c.model_settings, [&](const Setting& o) { return sets_same_thing(o.key, s.key); });
  c.model_settings.push_back(s);
}
}  // namespace

void apply_setting(SceneConfig& c, const Setting& given) {
  const Setting s = with_listed_key(c, given);
  try {
    if (const SceneKey* row = scene_key_named(c, s.key)) row->apply(c, s.key, s.value);
    else apply_model_setting(c, s);
  } catch (const UsageError& e) {
    throw UsageError(s.origin + ": " + e.what());
  }
}

}  // namespace vibra::scenes
