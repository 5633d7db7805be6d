// The command line vibra was started with, kept for pages and metadata to show.
#include "cli/command_line.hpp"

#include "core/input/shown_path.hpp"

namespace vibra::cli {

namespace {
std::string& stored() {
  static std::string line;
  return line;
}
}  // namespace

std::string shell_quoted(const std::string& argument) {
  const bool plain = !argument.empty() && argument.find_first_not_of("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz"
                                                                     "0123456789-_./=:,+%@") == std::string::npos;
  if (plain) return argument;
  std::string out = "'";
  for (char c : argument) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

void remember_command_line(int argc, char** argv) {
  // "vibra", not the path it was run by; paths relative to here, not the folders above (core/input/shown_path.hpp).
  std::string& line = stored();
  line = "vibra";
  for (int i = 1; i < argc; ++i) line += ' ' + shell_quoted(shown_argument(argv[i]));
}

const std::string& command_line() { return stored(); }

}  // namespace vibra::cli
