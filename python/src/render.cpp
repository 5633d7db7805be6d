// vibra.render: a scene's video or one still, written through the same
// render job as `vibra render`, with the GIL released and Ctrl-C (or a
// notebook's stop button) stopping it cleanly.
#include <optional>

#include "bindings.hpp"
#include "core/error.hpp"
#include "core/input/input_files.hpp"
#include "core/input/value_ranges.hpp"
#include "render/output/stop_signal.hpp"
#include "jobs/live_page_job.hpp"
#include "jobs/render_job.hpp"

namespace vibra::python {

namespace {
void render(const std::string& scene, const std::vector<std::pair<std::string, std::string>>& settings,
            const std::string& output, std::optional<double> at, bool frame_per_step, bool frames_player,
            const render::VideoSettings& video, bool quiet) {
  PythonStop stop;  // first: a Ctrl-C from here on stops the call, and leaves nothing
  forget_input_files();  // each call is a run of its own
  scenes::RenderRequest request;
  request.scene = scenes::load_scene(scene);
  for (const auto& [key, value] : settings) {
    render::throw_if_stop_requested();  // thousands of notes are read one by one
    scenes::apply_setting(request.scene, {key, value, "vibra.render"});
  }
  if (frame_per_step) request.scene.frame_per_step = true;
  request.output = output;
  // The same table of ranges as the command line's options (-1 and 0: the defaults).
  if (at) in_range("--at", *at, std::to_string(*at));
  if (video.crf != -1) in_range("--crf", video.crf, std::to_string(video.crf));
  if (video.threads != 0) in_range("--threads", video.threads, std::to_string(video.threads));
  request.at = at;
  request.frames_player = frames_player;
  request.quiet = quiet;
  request.video = video;
  py::gil_scoped_release release;
  scenes::run_render(request);
}
/// vibra.explore: the live page of `vibra render SCENE -o PAGE.html --live`.
void live_page(const std::string& scene, const std::vector<std::pair<std::string, std::string>>& settings,
               const std::string& output, bool quiet) {
  PythonStop stop;
  forget_input_files();
  scenes::LivePageRequest request{scene, scenes::load_scene(scene), {}, output, false, quiet};
  for (const auto& [key, value] : settings) {
    scenes::apply_setting(request.scene, {key, value, "vibra.explore"});
    request.base.push_back(key + "=" + value);
  }
  py::gil_scoped_release release;
  scenes::run_live_page(request);
}
}  // namespace

void bind_render(py::module_& m) {
  m.def(
      "render",
      [](const std::string& scene, const std::vector<std::pair<std::string, std::string>>& settings,
         const std::string& output, std::optional<double> at, bool frame_per_step, bool frames_player,
         const std::string& codec, const std::string& quality, int crf, const std::string& preset, int threads,
         bool transparent, bool quiet) {
        render::VideoSettings video{codec, quality, crf, preset, threads, transparent, ""};
        render(scene, settings, output, at, frame_per_step, frames_player, video, quiet);
      },
      py::arg("scene"), py::arg("settings"), py::arg("output"), py::arg("at"), py::arg("frame_per_step"),
      py::arg("frames_player"), py::arg("codec"), py::arg("quality"), py::arg("crf"), py::arg("preset"),
      py::arg("threads"), py::arg("transparent"), py::arg("quiet"));
  m.def("scene_names", &scenes::builtin_scene_names);
  m.def("live_page", &live_page, py::arg("scene"), py::arg("settings"), py::arg("output"), py::arg("quiet"));
}

}  // namespace vibra::python
