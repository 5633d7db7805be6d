// The commands, their options and the words each takes, read from the CLI11 definitions themselves: what the man pages and the shell completions are written from.
#pragma once
#include <CLI/CLI.hpp>
#include <string>
#include <vector>

namespace vibra::cli {

/// The words a value may be, for completion (and the man pages' lists).
enum class Words {
  none,         ///< anything: a number, a text
  files,        ///< any file name (an output)
  toml_files,   ///< scene files and storyboards
  video_files,  ///< .mp4 and .webm (vibra concat's parts)
  models,       ///< the model names
  scenes,       ///< built-in scenes and model names, or a scene file
  schemes,      ///< the scheme names
  keys,         ///< KEY= of every model and scene key, KEY=CHOICE for keys with choices
  commands,     ///< the commands (vibra help COMMAND)
  choices,      ///< the option's own list (OptionEntry::choices)
};

struct OptionEntry {
  std::vector<std::string> names;  ///< "-o", "--output"; a positional's one name, "MODEL"
  std::string value;               ///< what it takes ("PATH", "NUMBER"); "" for a flag
  std::string description, default_value;
  bool required = false;
  Words words = Words::none;
  std::vector<std::string> choices;  ///< for Words::choices
};

struct CommandEntry {
  std::string name;  ///< "convergence"; the root's "vibra"
  std::string path;  ///< "vibra analyze convergence"
  std::string description, footer;
  std::vector<OptionEntry> positionals, options;  ///< visible ones: hidden options are the build's
  std::vector<CommandEntry> subcommands;
};

/// The app and every command under it, in the order --help lists them.
CommandEntry command_catalog(const CLI::App& app);

/// The words of `kind` (not files: the shell lists those), in a fixed order.
std::vector<std::string> completion_words(Words kind, const CommandEntry& root);

/// "--output" of {"-o", "--output"}: the name a man page and a shell script use for it.
const std::string& longest_name(const OptionEntry&);

}  // namespace vibra::cli
