// vibra.plot: a model's run drawn as a figure (PNG, SVG, PDF) or a page of plots, by the same plot job as `vibra plot`.
#include "bindings.hpp"
#include "core/input/input_files.hpp"
#include "jobs/plot_job.hpp"

namespace vibra::python {

void bind_plot(py::module_& m) {
  m.def(
      "plot",
      [](const std::string& model, const std::vector<std::string>& settings, const std::string& output,
         const std::string& panels, const std::string& size, const std::string& compare, const std::string& annotate,
         bool transparent) {
        PythonStop stop;       // first: a Ctrl-C from here on stops the call, and leaves nothing
        forget_input_files();  // each call is a run of its own
        app::PlotRequest request{model, settings, output, panels, size, {}, annotate, transparent, "vibra.plot"};
        if (!compare.empty()) request.compare.push_back(compare);
        py::gil_scoped_release release;
        return app::run_plot(request);
      },
      py::arg("model"), py::arg("settings"), py::arg("output"), py::arg("panels"), py::arg("size"),
      py::arg("compare"), py::arg("annotate"), py::arg("transparent"));
}

}  // namespace vibra::python
