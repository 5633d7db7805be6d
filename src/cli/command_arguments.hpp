// The command line as CLI11 is given it: `vibra help COMMAND` read as `vibra COMMAND --help`, and names under the one spelling rule.
#pragma once
#include <CLI/CLI.hpp>
#include <string>
#include <vector>

namespace vibra::cli {

/// argv[1..] as `app` parses them:
///  - `help [COMMAND...]` becomes `[COMMAND...] --help`, so `vibra help X` is
///    exactly `vibra X --help`;
///  - command words are spelled as the commands are listed, and long option
///    names with hyphens: a hyphen and an underscore are one letter
///    (core/input/name_spelling.hpp), so `fd_accuracy` is `fd-accuracy` and
///    `--energy_bars` is `--energy-bars`. Values are never changed; nothing
///    after a bare `--` is.
std::vector<std::string> command_arguments(const CLI::App& app, int argc, const char* const* argv);

}  // namespace vibra::cli
