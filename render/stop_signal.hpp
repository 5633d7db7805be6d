#pragma once
// Cooperative cancellation for long work: SIGINT/SIGTERM set a flag that
// render and output loops poll between frames, so they can stop cleanly,
// remove their temporary files and exit with 128 + signal.

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

}  // namespace vibra::render
