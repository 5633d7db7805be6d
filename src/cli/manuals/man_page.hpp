// The man pages vibra(1) and vibra-COMMAND(1), written in roff from the CLI's own definitions (command_catalog.hpp) and registries.
#pragma once
#include <CLI/CLI.hpp>
#include <string>

namespace vibra::cli {

/// The roff source of one page: "vibra" gives vibra(1) (the commands, the
/// scenes, models and schemes, the spelling rule); a command's name gives
/// vibra-COMMAND(1) (its arguments, options, experiments and examples).
/// Throws UsageError naming the pages for any other name.
std::string man_page(const CLI::App& app, const std::string& page);

}  // namespace vibra::cli
