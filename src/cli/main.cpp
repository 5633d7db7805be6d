#include <csignal>
#include <cstdio>
#include <string>

#include "cli/command_line.hpp"
#include "cli/commands.hpp"
#include "core/error.hpp"
#include "render/output_error.hpp"
#include "render/stop_signal.hpp"

int main(int argc, char** argv) {
  // A closed pipe (`vibra solve ... | head`) shows up as a failed write that
  // each command handles quietly, rather than killing us mid-buffer.
  std::signal(SIGPIPE, SIG_IGN);
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
        return 2;
      }
    }
    app.parse(argc, argv);
    return 0;
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);
    std::fprintf(stderr, "vibra: error: %s (see vibra --help)\n", e.what());
    return 2;
  } catch (const vibra::render::Interrupted& e) {
    std::fprintf(stderr, "vibra: interrupted by signal %d; %s\n", e.signal, e.outcome);
    return 128 + e.signal;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "vibra: error: %s\n", e.what());
    return 2;
  }
}
