// Ctrl-C in Python stops vibra's work within a second, through vibra's one stop flag (core/stop_flag.hpp).
#include <chrono>
#include <csignal>
#include <thread>

#include "bindings.hpp"
#include "core/stop_flag.hpp"

namespace vibra::python {

namespace {
constexpr auto kPollEvery = std::chrono::milliseconds(20);  // a GIL round trip at most this often

std::atomic<std::thread::id> g_caller;  ///< the thread that called into vibra: only it may run Python's handlers
PyObject *g_type = nullptr, *g_value = nullptr, *g_trace = nullptr;  ///< what Python's handler raised (GIL held)

/// Runs Python's signal handlers (a Ctrl-C Python noted before vibra's
/// handlers were in place, or one `_thread.interrupt_main()` sent); keeps
/// what they raise for the error translator. Called at each look at the stop flag.
int poll_python() {
  if (std::this_thread::get_id() != g_caller.load(std::memory_order_relaxed)) return 0;
  static thread_local std::chrono::steady_clock::time_point next;
  const auto now = std::chrono::steady_clock::now();
  if (now < next) return 0;
  next = now + kPollEvery;
  py::gil_scoped_acquire gil;
  if (PyErr_CheckSignals() == 0) return 0;
  PyErr_Fetch(&g_type, &g_value, &g_trace);
  return SIGINT;
}
}  // namespace

PythonStop::PythonStop() {
  if (PyErr_CheckSignals() != 0) throw py::error_already_set();  // a Ctrl-C before the call: nothing done
  g_caller = std::this_thread::get_id();
  set_stop_poll(poll_python);
}

PythonStop::~PythonStop() {
  set_stop_poll(nullptr);
  g_caller = std::thread::id();
  if (g_type) take_stop_signal();  // Python has acted on it: the handlers below must not raise it again
}

bool restore_python_interrupt() {
  if (!g_type) return false;
  PyErr_Restore(g_type, g_value, g_trace);
  g_type = g_value = g_trace = nullptr;
  return true;
}

}  // namespace vibra::python
