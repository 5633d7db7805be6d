// The command line vibra was started with, kept for pages and metadata to show.
#pragma once
#include <string>

namespace vibra::cli {

/// Keeps the command line vibra was started with, for pages to show: as
/// "vibra ..." whatever path ran it, absolute paths shown by shown_argument.
void remember_command_line(int argc, char** argv);

/// The command line, each argument quoted for a POSIX shell where it needs
/// it, so it can be pasted to run again ("" before remember_command_line).
const std::string& command_line();

/// One argument as a POSIX shell reads it back: as it is when plain, else in single quotes.
std::string shell_quoted(const std::string& argument);

}  // namespace vibra::cli
