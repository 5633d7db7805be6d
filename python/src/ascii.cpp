// vibra.ascii_lines: the ASCII plotter's lines, one per time step, as they
// are made (constant memory; T=inf runs until the consumer stops).
#include "jobs/ascii_plot.hpp"
#include "bindings.hpp"

namespace vibra::python {

namespace {
class AsciiLines {
 public:
  explicit AsciiLines(const app::AsciiPlotOptions& options) : plot_(options) {}

  std::string next() {
    if (!legend_done_) {
      legend_done_ = true;
      if (!plot_.legend().empty()) return plot_.legend();
    }
    if (finished_) throw py::stop_iteration();
    std::string line(plot_.line());
    finished_ = !plot_.advance();
    return line;
  }

 private:
  app::AsciiPlot plot_;
  bool legend_done_ = false, finished_ = false;
};
}  // namespace

void bind_ascii(py::module_& m) {
  py::class_<AsciiLines>(m, "AsciiLines")
      .def(py::init([](const std::string& model, const std::vector<std::string>& settings, int width,
                       const std::string& symbols, std::optional<double> ymin, std::optional<double> ymax, bool exact,
                       const std::string& counter, const std::vector<std::string>& columns, bool legend) {
             return std::make_unique<AsciiLines>(
                 app::AsciiPlotOptions{model, settings, width, symbols, ymin, ymax, exact, counter, columns, legend});
           }),
           py::arg("model"), py::arg("settings"), py::arg("width"), py::arg("symbols"), py::arg("ymin"),
           py::arg("ymax"), py::arg("exact"), py::arg("counter"), py::arg("columns"), py::arg("legend"))
      .def("__iter__", [](py::object self) { return self; })
      .def("__next__", &AsciiLines::next);
}

}  // namespace vibra::python
