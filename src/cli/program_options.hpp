// The options of vibra itself rather than of a command: --version, `vibra help COMMAND`, and the hidden generators of the man pages and shell completions.
#pragma once
#include <CLI/CLI.hpp>

namespace vibra::cli {

/// Adds to the top-level app, after every command is added (the generators
/// walk the commands when they run):
///  - --version: "vibra X.Y.Z (git DESCRIBE)", exit 0;
///  - the command `help [COMMAND...]`, listed with the commands; the command
///    line is rewritten before parsing (command_arguments.hpp), so this entry
///    only shows it in --help, the man pages and the completions;
///  - hidden --man PAGE: the roff source of vibra(1) (PAGE vibra) or of
///    vibra-COMMAND(1) (man_page.hpp), on standard output;
///  - hidden --completion SHELL: the bash, zsh or fish completion script.
void add_program_options(CLI::App& app);

}  // namespace vibra::cli
