// Parses argv and runs the command it names, as the vibra executable does; every error one line on stderr.
#pragma once

namespace vibra::cli {

/// Parses `argv` and runs the command it names, as the `vibra` executable
/// does; every error is one line on stderr. Returns the exit code: 0, 2 for
/// any error, 128 + N after signal N. A non-zero code has been reported.
/// Separate from main so the argv fuzz target (tests/fuzz) runs it too.
int run_command_line(int argc, char** argv);

}  // namespace vibra::cli
