// Reads command_catalog.hpp's entries off the CLI11 app; which words an option takes is the policy table below.
#include "cli/command_catalog.hpp"

#include <algorithm>
#include <map>

#include "core/models/model.hpp"
#include "core/input/name_spelling.hpp"
#include "core/scheme.hpp"
#include "scenes/config/scene_config.hpp"

namespace vibra::cli {

namespace {
/// The words of a value, by the positional's or the long option's name.
const std::map<std::string, Words>& words_by_name() {
  static const std::map<std::string, Words> table = {
      {"MODEL", Words::models},       {"SCENE", Words::scenes},       {"STORYBOARD", Words::toml_files},
      {"PART", Words::video_files},   {"COMMAND", Words::commands},   {"--output", Words::files},
      {"--set", Words::keys},         {"--compare", Words::keys},     {"--scheme", Words::schemes},
      {"--schemes", Words::schemes},
  };
  return table;
}

/// The choices of the scene key an option is named after (--layout, --window-mode), but not true/false.
std::vector<std::string> scene_key_choices(const std::string& option) {
  for (const KeySpec& key : scenes::scene_keys())
    if (option.starts_with("--") && same_name(option.substr(2), key.name) && key.choices.size() > 2) return key.choices;
  return {};
}

/// "PATH" of CLI11's "TEXT:PATH": the last word is the most telling.
std::string value_name(const CLI::Option& option) {
  if (option.get_type_size_max() == 0) return "";
  const std::string type = option.get_type_name();
  return type.substr(type.rfind(':') + 1);
}

OptionEntry option_entry(const CLI::Option& option) {
  OptionEntry entry;
  for (const auto& s : option.get_snames()) entry.names.push_back("-" + s);
  for (const auto& l : option.get_lnames()) entry.names.push_back("--" + l);
  entry.value = value_name(option);
  if (entry.names.empty()) entry.names.push_back(entry.value = option.get_name(true));  // a positional: MODEL
  entry.description = option.get_description();
  entry.default_value = option.get_default_str();
  entry.required = option.get_required();
  if (const auto row = words_by_name().find(longest_name(entry)); row != words_by_name().end()) entry.words = row->second;
  if (entry.choices = scene_key_choices(longest_name(entry)); !entry.choices.empty()) entry.words = Words::choices;
  return entry;
}

CommandEntry command_entry(const CLI::App& app, const std::string& parent_path) {
  CommandEntry entry;
  entry.name = parent_path.empty() ? "vibra" : app.get_name();
  entry.path = parent_path.empty() ? "vibra" : parent_path + " " + app.get_name();
  entry.description = app.get_description();
  entry.footer = app.get_footer();
  for (const CLI::Option* option : app.get_options()) {
    if (option->get_group().empty()) continue;  // hidden: the build's generators
    (option->nonpositional() ? entry.options : entry.positionals).push_back(option_entry(*option));
  }
  for (const CLI::App* sub : app.get_subcommands({})) entry.subcommands.push_back(command_entry(*sub, entry.path));
  return entry;
}

void add_unique(std::vector<std::string>& words, const std::string& word) {
  if (std::find(words.begin(), words.end(), word) == words.end()) words.push_back(word);
}

/// KEY= for every key a scene or a model takes; KEY=CHOICE for each choice of a key that has them.
std::vector<std::string> key_words() {
  std::vector<KeySpec> specs = scenes::scene_keys();
  for (const auto& model : all_models()) {
    const Parameters keys = model_parameters(model);  // held: the loop reads its member
    specs.insert(specs.end(), keys.specs().begin(), keys.specs().end());
  }
  std::vector<std::string> words;
  for (const KeySpec& key : specs) {
    if (key.choices.empty()) add_unique(words, key.name + "=");
    for (const auto& choice : key.choices) add_unique(words, key.name + "=" + choice);
  }
  return words;
}
}  // namespace

const std::string& longest_name(const OptionEntry& option) {
  return *std::max_element(option.names.begin(), option.names.end(),
                           [](const std::string& a, const std::string& b) { return a.size() < b.size(); });
}

CommandEntry command_catalog(const CLI::App& app) { return command_entry(app, ""); }

std::vector<std::string> completion_words(Words kind, const CommandEntry& root) {
  std::vector<std::string> words;
  if (kind == Words::scenes)
    for (const auto& name : scenes::builtin_scene_names()) add_unique(words, name);
  if (kind == Words::models || kind == Words::scenes)
    for (const auto& model : all_models()) add_unique(words, model.name);
  if (kind == Words::schemes)
    for (const auto& scheme : all_schemes()) words.emplace_back(scheme.name);
  if (kind == Words::commands)
    for (const auto& command : root.subcommands) words.push_back(command.name);
  if (kind == Words::keys) words = key_words();
  return words;
}

}  // namespace vibra::cli
