// Parses argv and runs the command it names, as the vibra executable does; every error one line on stderr.
#include "cli/run_command_line.hpp"

#include <cstdio>
#include <new>
#include <sstream>
#include <string>

#include "cli/command_arguments.hpp"
#include "cli/command_line.hpp"
#include "cli/commands.hpp"
#include "cli/option_checks.hpp"
#include "cli/program_options.hpp"
#include "core/error.hpp"
#include "core/input/quoted_value.hpp"
#include "core/time_mesh.hpp"
#include "render/output/standard_output.hpp"
#include "render/output/stop_signal.hpp"

namespace vibra::cli {

CLI::Option* add_output_option(CLI::App& cmd, std::string& path, const std::string& help) {
  return cmd.add_option("-o,--output", path, help)->check(CLI::Validator(
      [](const std::string& value) {
        return value.empty() ? std::string("the output path is empty: give a file name, e.g. -o out.mp4") : std::string();
      },
      "PATH"));
}

void add_allow_unstable_flag(CLI::App& cmd) {
  cmd.add_flag_callback("--allow-unstable", [] { allow_unstable_steps(); },
                        "Run a dt above the scheme's stability limit (with a warning) instead of refusing it");
}

namespace {
/// --help and CLI11's other exits with code 0: the text goes through the
/// same checked writes as every other output.
int print_exit_text(const CLI::App& app, const CLI::Error& e) {
  std::ostringstream text;
  const int code = app.exit(e, text);
  try {
    render::print_standard_output(text.str());
  } catch (const ReportedExit& e) {
    return e.code;
  } catch (const render::StandardOutputFailed&) {
  }
  return code;
}

/// What is wrong with the command `words` name, for its one line: none
/// given, or not one of vibra's; "" when they name one (or start with an option).
std::string command_word_problem(const CLI::App& app, const std::vector<std::string>& words) {
  std::string names;
  bool known = false;
  for (const CLI::App* sub : app.get_subcommands({})) {
    known |= !words.empty() && sub->get_name() == words.front();
    names += (names.empty() ? "" : ", ") + sub->get_name();
  }
  if (words.empty()) return "no command given: choose one of " + names + " (see vibra --help; vibra --version says which vibra)";
  if (known || words.front()[0] == '-') return "";
  return "unknown command '" + quoted_value(words.front()) + "': choose one of " + names + " (see vibra --help)";
}

/// The one line of an error: "vibra: error: ...", at most about 240
/// characters whatever the message quotes (docs/reliability.md, "Messages").
int report_error(const std::string& message, int code = 2) {
  std::fprintf(stderr, "vibra: error: %s\n", one_line_message(message).c_str());
  return code;
}
}  // namespace

int run_command_line(int argc, char** argv) {
  allow_unstable_steps(false);  // only this command line's --allow-unstable counts
  // Named: usage lines say "vibra", not the path the binary was run by.
  CLI::App app{"vibra: vibration ODEs from Linge & Langtangen chapter 1, solved, drawn, animated", "vibra"};
  app.require_subcommand(1);
  add_solve_command(app);
  add_render_command(app);
  add_ascii_command(app);
  add_plot_command(app);
  add_analyze_command(app);
  add_concat_command(app);
  add_lecture_command(app);
  add_chapter_command(app);
  refuse_empty_values(app);
  add_program_options(app);  // after every command: `help` is listed last, the generators walk them all
  try {
    const std::vector<std::string> words = command_arguments(app, argc, argv);
    if (const std::string problem = command_word_problem(app, words); !problem.empty()) return report_error(problem);
    std::vector<const char*> parsed = {"vibra"};
    for (const std::string& word : words) parsed.push_back(word.c_str());
    app.parse(static_cast<int>(parsed.size()), parsed.data());
    return 0;
  } catch (const ReportedExit& e) {
    return e.code;
  } catch (const render::StandardOutputFailed&) {
    return 0;  // recorded: main's check at exit reports it, or not for EPIPE
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return print_exit_text(app, e);  // --help
    return report_error(std::string(e.what()) + " (see vibra --help)");
  } catch (const Interrupted& e) {
    std::fprintf(stderr, "vibra: interrupted by signal %d; %s\n", e.signal, e.outcome);
    return 128 + e.signal;
  } catch (const std::bad_alloc&) {
    // Never the bare "std::bad_alloc": name what asked for the memory.
    return report_error("out of memory: " + quoted_value(command_line(), 80) +
                        " needs more memory than this machine gives it: ask for less (a smaller --size, T or "
                        "periods, a larger dt or --every)");
  } catch (const std::exception& e) {
    return report_error(e.what());
  }
}

}  // namespace vibra::cli
