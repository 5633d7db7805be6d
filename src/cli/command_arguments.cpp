// Rewrites argv by the rules of command_arguments.hpp before CLI11 sees it.
#include "cli/command_arguments.hpp"

#include <algorithm>

#include "core/input/name_spelling.hpp"

namespace vibra::cli {

namespace {
/// "--energy_bars=1" as "--energy-bars=1": only the name, before any '='.
std::string long_option_spelled(std::string argument) {
  const std::size_t end = std::min(argument.find('='), argument.size());
  std::replace(argument.begin() + 2, argument.begin() + static_cast<std::ptrdiff_t>(end), '_', '-');
  return argument;
}

/// The subcommand of `app` that `word` names, or nullptr.
const CLI::App* subcommand_named(const CLI::App& app, const std::string& word) {
  for (const CLI::App* sub : app.get_subcommands({}))
    if (same_name(sub->get_name(), word)) return sub;
  return nullptr;
}
}  // namespace

std::vector<std::string> command_arguments(const CLI::App& app, int argc, const char* const* argv) {
  std::vector<std::string> words(argv + std::min(argc, 1), argv + argc);
  const bool asks_help = !words.empty() && words.front() == "help";
  if (asks_help) words.erase(words.begin());
  const CLI::App* command = &app;  // the command the next word may name a subcommand of
  bool after_separator = false;
  for (std::string& word : words) {
    if (after_separator) continue;
    if (word == "--") after_separator = true;
    else if (word.size() > 2 && word.starts_with("--")) word = long_option_spelled(word);
    if (const CLI::App* sub = command ? subcommand_named(*command, word) : nullptr) word = sub->get_name();
    command = command && !word.starts_with("-") ? subcommand_named(*command, word) : nullptr;
  }
  if (asks_help) words.push_back("--help");
  return words;
}

}  // namespace vibra::cli
