// vibra's exceptions as Python's: bad input is a ValueError with the command
// line's one-line message, a blow-up a SolutionError with its step and time.
#include "bindings.hpp"
#include "core/error.hpp"
#include "render/output/output_error.hpp"
#include "render/output/stop_signal.hpp"

namespace vibra::python {

void bind_errors(py::module_& m) {
  // Kept for the life of the interpreter, as the translator refers to it.
  static PyObject* solution_error = PyErr_NewExceptionWithDoc(
      "vibra.SolutionError",
      "The solution became non-finite, or an implicit step did not converge.\n"
      "Attributes: step (the step number) and t (its time).",
      PyExc_RuntimeError, nullptr);
  m.attr("SolutionError") = py::handle(solution_error);
  py::register_exception_translator([](std::exception_ptr error) {
    try {
      if (error) std::rethrow_exception(error);
    } catch (const UsageError& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    } catch (const SolutionError& e) {
      py::object exception = py::reinterpret_borrow<py::object>(solution_error)(e.what());
      exception.attr("step") = e.step;
      exception.attr("t") = e.t;
      PyErr_SetObject(solution_error, exception.ptr());
    } catch (const render::OutputError& e) {
      PyErr_SetString(PyExc_OSError, e.what());
    } catch (const render::Interrupted&) {
      // What Python's handler raised during a poll, or the signal raised
      // again for Python's handler: let it speak.
      if (!restore_python_interrupt() && PyErr_CheckSignals() == 0) PyErr_SetNone(PyExc_KeyboardInterrupt);
    } catch (const std::bad_alloc&) {
      // Never the bare "std::bad_alloc": say what to ask for instead, as the command line does.
      PyErr_SetString(PyExc_MemoryError,
                      "out of memory: this call needs more memory than this machine gives it: ask for less (a "
                      "smaller size, T or periods, a larger dt or every, or vibra.stream for a long run)");
    }
  });
}

}  // namespace vibra::python
