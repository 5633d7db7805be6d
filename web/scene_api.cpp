// The live page's C API: a scene set up from KEY=VALUE settings, drawn at any time as 2D-canvas operations by the same scene code.
#include <exception>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "setting_lines.hpp"
#include "core/input/quoted_value.hpp"
#include "web/live_scene.hpp"

namespace {

std::optional<vibra::web::LiveScene> live;
std::string last_error;

/// Runs `work`, turning a refusal into the CLI's one-line reason: 0 done,
/// 2 bad input, 1 another fault.
template <class Work>
int guarded(Work&& work) {
  last_error.clear();
  try {
    work();
    return 0;
  } catch (const vibra::UsageError& e) {
    last_error = vibra::one_line_message(e.what());
    return 2;
  } catch (const vibra::SolutionError& e) {
    last_error = vibra::one_line_message(e.what());
    return 2;
  } catch (const std::exception& e) {
    last_error = vibra::one_line_message(e.what());
    return 1;
  }
}

}  // namespace

extern "C" {

/// Sets up SCENE (a built-in scene's name) with one KEY=VALUE a line, as
/// `vibra render SCENE --set KEY=VALUE` takes them (scene keys such as
/// width and height too). The scene is solved and recorded; 0 when ready.
int vibra_scene_open(const char* scene, const char* settings) {
  return guarded([&] {
    live.reset();
    live.emplace(scene ? scene : "", vibra::web::lines_of(settings));
  });
}

/// Sets up the scene of a scene file, from its name (for its messages) and
/// its text, which the page carries, with settings as vibra_scene_open.
int vibra_scene_open_file(const char* file, const char* text, const char* settings) {
  return guarded([&] {
    live.reset();
    live.emplace(file ? file : "", vibra::web::lines_of(settings), text ? text : "");
  });
}

/// Draws the scene at simulated time t; its operations are then read by
/// vibra_scene_numbers and vibra_scene_strings. `whole_chain` 1: as the
/// still at t (LiveScene::draw); 0: at once.
int vibra_scene_draw(double t, int whole_chain) {
  return guarded([&] {
    if (!live) throw vibra::UsageError("no scene is open: call vibra_scene_open first");
    live->draw(t, whole_chain != 0);
  });
}

const char* vibra_scene_error() { return last_error.c_str(); }
const double* vibra_scene_numbers() { return live ? live->commands().numbers().data() : nullptr; }
int vibra_scene_number_count() { return live ? int(live->commands().numbers().size()) : 0; }
const char* vibra_scene_strings() {
  static std::string joined;
  joined = live ? live->commands().joined_strings() : std::string();
  return joined.c_str();
}
/// The run's end time, the frame size, and the frames per second of its clock.
double vibra_scene_end_time() { return live ? live->end_time() : 0; }
int vibra_scene_width() { return live ? live->width() : 0; }
int vibra_scene_height() { return live ? live->height() : 0; }
double vibra_scene_fps() { return live ? live->fps() : 0; }
/// The simulated time frame k of the scene's clock shows (its playback).
double vibra_scene_frame_time(int k) { return live ? live->frame_time(k) : 0; }
int vibra_scene_frame_count() { return live ? int(live->frame_count()) : 0; }
/// How many strokes and paints the page's canvas was not handed since the
/// scene was opened (a surface as their source): the tests hold every scene to 0.
int vibra_scene_dropped() { return live ? live->dropped() : 0; }

}  // extern "C"
