#include "cli/command_line.hpp"

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
  std::string& line = stored();
  line.clear();
  for (int i = 0; i < argc; ++i) {
    if (i) line += ' ';
    line += shell_quoted(argv[i]);
  }
}

const std::string& command_line() { return stored(); }

}  // namespace vibra::cli
