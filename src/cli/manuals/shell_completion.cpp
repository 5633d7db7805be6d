// Picks the completion writer for a shell from the table of shells; the quoting every writer shares.
#include "cli/manuals/shell_completion.hpp"

#include "core/error.hpp"

namespace vibra::cli {

namespace {
struct ShellWriter {
  const char* shell;
  std::string (*write)(const CommandEntry&);
};
constexpr ShellWriter kShells[] = {{"bash", bash_completion}, {"zsh", zsh_completion}, {"fish", fish_completion}};
}  // namespace

std::string completion_script(const CLI::App& app, const std::string& shell) {
  for (const auto& writer : kShells)
    if (shell == writer.shell) return writer.write(command_catalog(app));
  throw UsageError("no completion for shell '" + shell + "': choose bash, zsh or fish");
}

std::string single_quoted(const std::string& text) {
  std::string out = "'";
  for (char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

std::string words_line(Words kind, const CommandEntry& root, bool quote_each) {
  std::string out;
  for (const auto& word : completion_words(kind, root)) out += (out.empty() ? "" : " ") + (quote_each ? single_quoted(word) : word);
  return out;
}

std::string kind_name(Words kind) {
  static const char* const names[] = {"none",   "files",   "toml_files", "video_files", "models",
                                      "scenes", "schemes", "keys",       "commands",    "choices"};
  return names[static_cast<int>(kind)];
}

std::string value_kind(const OptionEntry& option) {
  if (option.words != Words::choices) return kind_name(option.words);
  std::string list;
  for (const auto& choice : option.choices) list += (list.empty() ? "" : " ") + choice;
  return "choices:" + list;
}

std::string value_arm(const CommandEntry& command, const std::string& name, const OptionEntry& option) {
  return "    " + single_quoted(command_key(command) + "|" + name) + ") REPLY=" + single_quoted(value_kind(option)) + ";;\n";
}

std::string command_key(const CommandEntry& command) {
  return command.path == "vibra" ? "" : command.path.substr(std::string("vibra ").size());
}

}  // namespace vibra::cli
