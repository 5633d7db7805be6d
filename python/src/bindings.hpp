// The parts of the module vibra._vibra, one file each.
// The pure-Python package vibra wraps them with keyword arguments and display
// objects.
#pragma once
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <memory>

#include "render/output/stop_signal.hpp"
#include <string>
#include <vector>

namespace vibra::python {

namespace py = pybind11;

void bind_errors(py::module_&);
void bind_solve(py::module_&);
void bind_ascii(py::module_&);
void bind_render(py::module_&);
void bind_lecture(py::module_&);
void bind_analyses(py::module_&);
void bind_plot(py::module_&);

/// For the life of a call into vibra's long work (render, lecture), made
/// with the GIL held before any work: vibra's SIGINT and SIGTERM handlers
/// (render::ScopedStopHandlers) and a poll, at every look at the stop flag,
/// of the signals Python has noted. Throws error_already_set when Python
/// already holds a Ctrl-C: the call does nothing.
class PythonStop {
 public:
  PythonStop();
  ~PythonStop();
  PythonStop(const PythonStop&) = delete;
  PythonStop& operator=(const PythonStop&) = delete;

 private:
  render::ScopedStopHandlers handlers_;
};

/// Raises (sets) what Python's signal handler raised during a poll, if it
/// did; the error translator calls it for vibra's Interrupted. GIL held.
bool restore_python_interrupt();

/// Uninitialised memory for a table of doubles, in huge pages when large
/// (a 400 MB run then faults in 200 times instead of 100000).
struct FreeTable {
  void operator()(double* data) const;
};
using TableMemory = std::unique_ptr<double[], FreeTable>;
TableMemory allocate_table(size_t rows, size_t columns);

/// A (rows, columns) float64 array in column-major order that views `data`
/// and owns it through a capsule: numpy frees it with the last view.
py::array_t<double> owning_array(TableMemory data, size_t rows, size_t columns);

}  // namespace vibra::python
