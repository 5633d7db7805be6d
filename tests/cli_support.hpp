#pragma once
// Runs the real `vibra` executable for end-to-end tests.
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <string>

namespace vibra::test {

struct CommandResult {
  int exit_code = -1;
  std::string out, err;
};

/// Runs `vibra ARGS` through the shell, capturing stdout and stderr.
inline CommandResult run_vibra(const std::string& args) {
  static int counter = 0;
  const auto dir = std::filesystem::temp_directory_path();
  const std::string err_path = (dir / ("vibra_cli_err_" + std::to_string(::getpid()) + "_" + std::to_string(counter++))).string();
  const std::string command = std::string(VIBRA_EXE) + " " + args + " 2>" + err_path;
  CommandResult result;
  std::FILE* pipe = ::popen(command.c_str(), "r");
  std::array<char, 4096> buffer;
  size_t n;
  while ((n = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0) result.out.append(buffer.data(), n);
  const int status = ::pclose(pipe);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  if (std::FILE* f = std::fopen(err_path.c_str(), "rb")) {
    while ((n = std::fread(buffer.data(), 1, buffer.size(), f)) > 0) result.err.append(buffer.data(), n);
    std::fclose(f);
  }
  std::filesystem::remove(err_path);
  return result;
}

/// A fresh empty directory under /tmp, removed by the destructor.
struct ScratchDirectory {
  std::filesystem::path path;
  ScratchDirectory() {
    static int counter = 0;
    path = std::filesystem::temp_directory_path() /
           ("vibra_test_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
    std::filesystem::remove_all(path);
    std::filesystem::create_directories(path);
  }
  ~ScratchDirectory() { std::filesystem::remove_all(path); }
  std::string operator/(const std::string& name) const { return (path / name).string(); }
  bool empty() const { return std::filesystem::is_empty(path); }
};

}  // namespace vibra::test
