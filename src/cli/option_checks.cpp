// CLI11 validators for numeric options, read as --set values are and held to the table of ranges.
#include "cli/option_checks.hpp"

#include "core/error.hpp"
#include "core/input/expression.hpp"
#include "core/input/value_ranges.hpp"

namespace vibra::cli {

CLI::Validator ranged(const std::string& option) {
  return CLI::Validator(
      [option](const std::string& value) {
        try {
          in_range(option, evaluate_constant(option, value), value);
          return std::string();
        } catch (const UsageError& e) {
          // CLI11 puts "--every: " in front: do not say the name twice.
          std::string message = e.what();
          if (message.starts_with(option + " ")) message.erase(0, option.size() + 1);
          return message;
        }
      },
      "NUMBER");
}

void refuse_empty_values(CLI::App& app) {
  for (CLI::Option* option : app.get_options()) {
    if (option->get_type_size_max() == 0) continue;  // a flag
    const std::string name = option->get_name();
    option->check(CLI::Validator(
        [name](const std::string& value) {
          if (value.find_first_not_of(" \t") != std::string::npos) return std::string();
          return "the value is empty: give one, or leave " + name + " out for its default";
        },
        ""));
  }
  for (CLI::App* sub : app.get_subcommands({})) refuse_empty_values(*sub);
}

}  // namespace vibra::cli
