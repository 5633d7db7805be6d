// vibra.lecture: a storyboard's shots played into one video, through the
// same lecture job as `vibra lecture`, with the GIL released and Ctrl-C (or
// a notebook's stop button) stopping it cleanly.
#include <optional>

#include "bindings.hpp"
#include "core/input/input_files.hpp"
#include "core/input/value_ranges.hpp"
#include "render/output/stop_signal.hpp"
#include "jobs/lecture_job.hpp"

namespace vibra::python {

void bind_lecture(py::module_& m) {
  m.def(
      "lecture",
      [](const std::string& storyboard, const std::string& output, std::optional<int> shot, const std::string& codec,
         const std::string& quality, int crf, const std::string& preset, int threads, bool force, bool quiet, bool mute,
         bool present, const std::string& shots_dir) {
        PythonStop stop;  // first: a Ctrl-C from here on stops the call, and leaves nothing
        forget_input_files();  // each call is a run of its own
        if (crf != -1) in_range("--crf", crf, std::to_string(crf));
        if (threads != 0) in_range("--threads", threads, std::to_string(threads));
        scenes::LectureRequest request;
        request.storyboard = storyboard;
        request.output = output;
        request.shot = shot;
        request.video = render::VideoSettings{codec, quality, crf, preset, threads, false, ""};
        request.force = force;
        request.quiet = quiet;
        request.mute = mute;
        request.present = present;
        request.shots_dir = shots_dir;
        py::gil_scoped_release release;
        scenes::run_lecture(request);
      },
      py::arg("storyboard"), py::arg("output"), py::arg("shot"), py::arg("codec"), py::arg("quality"), py::arg("crf"),
      py::arg("preset"), py::arg("threads"), py::arg("force"), py::arg("quiet"), py::arg("mute"),
      py::arg("present"), py::arg("shots_dir"));
}

}  // namespace vibra::python
