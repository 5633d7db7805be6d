#pragma once
#include <string>

namespace vibra::cli {

/// Keeps the command line vibra was started with, for pages to show: as
/// "vibra ..." whatever path ran it, absolute paths shown by shown_argument.
void remember_command_line(int argc, char** argv);

/// The command line, each argument quoted for a POSIX shell where it needs
/// it, so it can be pasted to run again ("" before remember_command_line).
const std::string& command_line();

}  // namespace vibra::cli
