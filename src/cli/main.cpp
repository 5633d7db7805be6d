// The vibra executable's entry point: runs the command line and checks standard output at exit.
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "cli/command_line.hpp"
#include "cli/run_command_line.hpp"
#include "render/output/standard_output.hpp"
#include "render/output/stop_signal.hpp"

namespace {
/// The command has put its one line on stderr: the check at exit adds no
/// second line.
bool reported = false;

/// Runs at exit, after main returns: every byte on standard output must have
/// been written (docs/reliability.md, "Standard output").
void check_standard_output() {
  const int error = vibra::render::close_standard_output();
  if (error == 0 || error == EPIPE || reported) return;  // EPIPE: the reader has gone, a pipeline's normal end
  std::fprintf(stderr, "vibra: error: writing %s: %s\n", vibra::render::standard_output_name().c_str(),
               std::strerror(error));
  std::_Exit(2);
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
  const int code = vibra::cli::run_command_line(argc, argv);
  reported = code != 0;
  return code;
}
