// The Python extension module vibra._vibra: registers each part of bindings.hpp and the stop flag for Ctrl-C.
#include "bindings.hpp"

#include "core/stop_flag.hpp"

PYBIND11_MODULE(_vibra, m) {
  m.doc() = "vibra's C++ core: solvers, scenes and analyses (use the package vibra)";
  vibra::quiet_long_work(true);  // a notebook's cell shows no stderr lines of the CLI's kind
  vibra::python::bind_errors(m);
  vibra::python::bind_solve(m);
  vibra::python::bind_ascii(m);
  vibra::python::bind_render(m);
  vibra::python::bind_lecture(m);
  vibra::python::bind_analyses(m);
  vibra::python::bind_plot(m);
}
