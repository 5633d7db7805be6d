#pragma once
// Cooperative cancellation for long work: SIGINT/SIGTERM set a flag that
// render and output loops poll between frames, so they can stop cleanly,
// remove their temporary files and exit with 128 + signal.

#include <csignal>

namespace vibra::render {

/// Installs SIGINT and SIGTERM handlers that only record the signal.
void install_stop_handlers();

/// The signal number that asked us to stop, or 0.
int stop_signal();

inline bool stop_requested() { return stop_signal() != 0; }

/// Thrown by loops that noticed stop_requested(); the CLI maps it to 128 + signal.
struct Interrupted {
  int signal;
  const char* outcome = "no partial output was kept";  // what the user finds afterwards
};

/// Throws Interrupted if a stop was requested.
void throw_if_stop_requested();

/// The stop handlers for the lifetime of the object, in a process that has
/// handlers of its own (the Python module inside an interpreter or a notebook
/// kernel). On destruction the handlers found are put back, and a signal
/// recorded meanwhile is forgotten and raised again, so the host's handler
/// sees it (Python then raises KeyboardInterrupt).
class ScopedStopHandlers {
 public:
  ScopedStopHandlers();
  ~ScopedStopHandlers();
  ScopedStopHandlers(const ScopedStopHandlers&) = delete;
  ScopedStopHandlers& operator=(const ScopedStopHandlers&) = delete;

 private:
  struct sigaction previous_[2];  // SIGINT's and SIGTERM's
};

}  // namespace vibra::render
