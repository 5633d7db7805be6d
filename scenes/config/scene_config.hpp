// SceneConfig: scene files, --set and flags read into one typed configuration of a render.
#pragma once
#include <string>
#include <vector>

#include "core/input/parameters.hpp"
#include "scenes/timing/pacing.hpp"
#include "scenes/config/scene_style.hpp"

namespace vibra::scenes {

/// One KEY=VALUE with where it came from ("pendulum.toml:4", "--set"), so
/// errors can point at it.
struct Setting {
  std::string key, value, origin;
};

/// Everything a render needs besides the output: the model and its settings,
/// frame size and timing, layout and style. Built from defaults, then a scene
/// file, then `--set`, then explicit flags, each overriding the one before.
struct SceneConfig {
  std::string name = "pendulum";
  std::string model = "pendulum";
  std::string diagram;  ///< the drawing (`vibra render --help` lists them); "" = the model's default
  std::vector<Setting> model_settings;
  int width = 1280, height = 720;
  double fps = 30;
  double speed = 0;  ///< simulated time per second of video; 0 = one small-oscillation period in 2 s
  bool frame_per_step = false;
  Layout layout = Layout::fbd_plot;
  /// Plot window: "" = the whole run; a time ("10") or periods ("8periods").
  std::string window;
  WindowMode window_mode = WindowMode::movement;
  /// Panels beside the diagram (layout fbd+plot), by name; empty = the diagram's own.
  std::vector<std::string> panels;
  bool energy_bars = false;  ///< kinetic, potential and dissipated energy beside the diagram
  /// Marks of the book's figures on the diagram, by name (scene key
  /// `annotate`, --annotate): "geometry" for the pendulum (Fig 1.21).
  std::vector<std::string> annotate;
  double drag_magnification = 5;
  /// Small vertical motions drawn this many times larger (the bumpy road);
  /// 0 = chosen from the run, 1 = true scale.
  double exaggerate = 0;
  SceneColors colors;
  /// "KEY=V1,V2,...": one run per value, drawn together; "" = one run.
  std::string compare;
  /// A title across the top of the frame; "" = none.
  std::string title;
  /// The model's equation of motion typeset under the title, and with a
  /// comparison of schemes each scheme's update formula in the legend.
  bool equation = false;
  /// Callouts "T0-T1: TEXT" (TEXT may hold $math$; "@PANEL" points at a
  /// panel's curve), each added by a `notes` setting.
  std::vector<std::string> notes;
  /// Slow motion and pauses (keys slow and pause, --slow, --pause).
  Pacing pacing;
};

/// The keys a scene has besides its model's (shown by `vibra render --help`).
const std::vector<KeySpec>& scene_keys();

/// A built-in scene by name (`pendulum`, `pendulum_book`) or a TOML file.
/// Throws UsageError naming the file, line and key for bad content.
SceneConfig load_scene(const std::string& name_or_path);
/// Whether load_scene takes `name_or_path` as a built-in scene or a model's
/// name (these come before files), not as a scene file.
bool names_builtin_scene(const std::string& name_or_path);
/// A scene from TOML text; `file` names it in messages ("lecture.toml").
SceneConfig parse_scene(const std::string& text, const std::string& file);

/// Applies one setting: a scene key, or else a key of the scene's model.
/// Throws UsageError with `origin`, suggesting the closest valid key.
void apply_setting(SceneConfig&, const Setting&);

/// The model's Parameters with the scene's model settings applied.
Parameters model_parameters_of(const SceneConfig&);

/// The settings a comparison's members share: the model settings without
/// the compared key (a scene file's value of it gives way to the
/// comparison's). Throws UsageError when --set gives the key too.
Parameters comparison_base_of(const SceneConfig&, const std::string& key);

/// The window width in time units (0 = whole run), given the model's period.
double window_width(const SceneConfig&, double period);

/// Parses "WxH"; throws UsageError unless both are 1..8192.
void parse_size(const std::string& text, int& width, int& height);

/// Names of the built-in scenes.
std::vector<std::string> builtin_scene_names();
/// A built-in scene's one-line description: the first comment line of its preset file.
std::string builtin_scene_summary(const std::string& name);

}  // namespace vibra::scenes
