// CLI11 validators for numeric options, read as --set values are and held to the table of ranges.
#pragma once
#include <CLI/CLI.hpp>
#include <string>

namespace vibra::cli {

/// A validator for a numeric option: the value is read as --set values are
/// (an expression) and must lie in the option's row of the one table of
/// ranges (core/input/value_ranges.hpp); the error says the range and the fix.
CLI::Validator ranged(const std::string& option);

/// Gives every option of `app` and of its subcommands that takes a value a
/// check that refuses an empty one (`--size ''`): an empty value is never
/// silently the default.
void refuse_empty_values(CLI::App& app);

}  // namespace vibra::cli
