// Shell completion scripts for bash, zsh and fish, written from the CLI's own definitions (command_catalog.hpp): commands, options, scene, model, scheme and key names, file kinds.
#pragma once
#include <CLI/CLI.hpp>
#include <string>

#include "cli/command_catalog.hpp"

namespace vibra::cli {

/// The script for `shell` ("bash", "zsh" or "fish"); throws UsageError naming them for any other.
std::string completion_script(const CLI::App& app, const std::string& shell);

/// Each shell's script from the catalog (bash_completion.cpp, zsh_completion.cpp, fish_completion.cpp).
std::string bash_completion(const CommandEntry& root);
std::string zsh_completion(const CommandEntry& root);
std::string fish_completion(const CommandEntry& root);

/// `text` inside single quotes for a POSIX shell (and zsh, fish): 'it'\''s'.
std::string single_quoted(const std::string& text);

/// The words of `kind` separated by spaces, each single-quoted when `quote_each`
/// (no word holds a space or a quote, so a list quoted whole is safe too).
std::string words_line(Words kind, const CommandEntry& root, bool quote_each);

/// The name a script gives a kind of word: "models", "toml_files".
std::string kind_name(Words kind);

/// The kind of word an option's value is, for a script's case statement:
/// kind_name, or "choices:A B C" with the option's own list.
std::string value_kind(const OptionEntry& option);

/// A command's path as the scripts key it: "" for vibra itself, "analyze convergence".
std::string command_key(const CommandEntry& command);

/// One arm of the bash and zsh scripts' _vibra_value: `'analyze energy|--schemes') REPLY='schemes';;`.
std::string value_arm(const CommandEntry& command, const std::string& name, const OptionEntry& option);

}  // namespace vibra::cli
