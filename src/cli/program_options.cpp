// --version, `vibra help`, and the hidden --man and --completion of program_options.hpp.
#include "cli/program_options.hpp"

#include <memory>
#include <string>
#include <vector>

#include "cli/build_version.hpp"
#include "cli/manuals/man_page.hpp"
#include "cli/manuals/shell_completion.hpp"
#include "render/output/standard_output.hpp"

namespace vibra::cli {

namespace {
/// Prints what a generator made and ends the run with exit code 0, as --help does.
[[noreturn]] void print_and_finish(const std::string& text) {
  render::print_standard_output(text);
  throw CLI::Success();
}
}  // namespace

void add_program_options(CLI::App& app) {
  app.set_version_flag("--version", version_text(), "Print vibra's version and the git describe of its build, then exit");
  auto commands = std::make_shared<std::vector<std::string>>();
  CLI::App* help = app.add_subcommand("help", "Show a command's help: vibra help COMMAND is vibra COMMAND --help");
  help->add_option("COMMAND", *commands, "A command (and an analyze experiment); none: vibra --help");
  const CLI::App* root = &app;
  app.add_option_function<std::string>(
         "--man", [root](const std::string& page) { print_and_finish(man_page(*root, page)); },
         "The man page PAGE (vibra or a command) in roff")
      ->group("");
  app.add_option_function<std::string>(
         "--completion", [root](const std::string& shell) { print_and_finish(completion_script(*root, shell)); },
         "The completion script for SHELL: bash, zsh or fish")
      ->group("");
}

}  // namespace vibra::cli
