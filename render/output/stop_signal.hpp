// Cooperative cancellation for long work: SIGINT/SIGTERM set a flag that render and output loops poll between frames, so they can stop cleanly, remove their temporary files and exit with 128 + signal.
#pragma once

#include <csignal>

#include "core/stop_flag.hpp"

namespace vibra::render {

/// Installs SIGINT and SIGTERM handlers that only record the signal.
void install_stop_handlers();

// The flag itself and Interrupted live in core (core/stop_flag.hpp).
using vibra::Interrupted;
using vibra::stop_signal;
using vibra::throw_if_stop_requested;

inline bool stop_requested() { return stop_signal() != 0; }

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
