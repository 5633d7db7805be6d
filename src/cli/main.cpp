#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <string>

#include "cli/command_line.hpp"
#include "cli/commands.hpp"
#include "core/error.hpp"
#include "core/time_mesh.hpp"
#include "render/output_error.hpp"
#include "render/standard_output.hpp"
#include "render/stop_signal.hpp"

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
}  // namespace vibra::cli

namespace {
/// main has put its one line on stderr and chosen the exit code: the check at
/// exit adds no second line.
bool reported = false;

int report(int code) {
  reported = true;
  return code;
}

/// Runs at exit, after main returns: every byte on standard output must have
/// been written (docs/reliability.md, "Standard output").
void check_standard_output() {
  const int error = vibra::render::close_standard_output();
  if (error == 0 || error == EPIPE || reported) return;  // EPIPE: the reader has gone, a pipeline's normal end
  std::fprintf(stderr, "vibra: error: writing %s: %s\n", vibra::render::standard_output_name().c_str(),
               std::strerror(error));
  std::_Exit(2);
}

/// --help and CLI11's other exits with code 0: the text goes through the
/// same checked writes as every other output.
int print_exit_text(const CLI::App& app, const CLI::Error& e) {
  std::ostringstream text;
  const int code = app.exit(e, text);
  try {
    vibra::render::print_standard_output(text.str());
  } catch (const vibra::render::StandardOutputFailed&) {
  }
  return code;
}
}  // namespace

int main(int argc, char** argv) {
  // A closed pipe (`vibra solve ... | head`) shows up as a failed write (EPIPE)
  // that ends the command quietly, rather than killing us mid-buffer.
  std::signal(SIGPIPE, SIG_IGN);
  vibra::render::keep_standard_descriptors();
  std::atexit(check_standard_output);
  vibra::render::install_stop_handlers();
  vibra::cli::remember_command_line(argc, argv);

  CLI::App app{"vibra: vibration ODEs from Linge & Langtangen chapter 1, solved, drawn, animated"};
  app.require_subcommand(1);
  vibra::cli::add_solve_command(app);
  vibra::cli::add_render_command(app);
  vibra::cli::add_ascii_command(app);
  vibra::cli::add_plot_command(app);
  vibra::cli::add_analyze_command(app);
  vibra::cli::add_concat_command(app);
  try {
    if (argc > 1 && argv[1][0] != '-') {
      std::string names;
      bool known = false;
      for (const CLI::App* sub : app.get_subcommands({})) {
        known |= sub->get_name() == argv[1];
        names += (names.empty() ? "" : ", ") + sub->get_name();
      }
      if (!known) {
        std::fprintf(stderr, "vibra: error: unknown command '%s': choose one of %s (see vibra --help)\n", argv[1],
                     names.c_str());
        return report(2);
      }
    }
    app.parse(argc, argv);
    return 0;
  } catch (const vibra::render::StandardOutputFailed&) {
    return 0;  // recorded: check_standard_output reports it, or not for EPIPE
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return print_exit_text(app, e);  // --help
    std::fprintf(stderr, "vibra: error: %s (see vibra --help)\n", e.what());
    return report(2);
  } catch (const vibra::render::Interrupted& e) {
    std::fprintf(stderr, "vibra: interrupted by signal %d; %s\n", e.signal, e.outcome);
    return report(128 + e.signal);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "vibra: error: %s\n", e.what());
    return report(2);
  }
}
