// stopped_after: a vibra run sent a signal partway, for the tests of Ctrl-C and SIGTERM.
#pragma once
#include <signal.h>
#include <sys/wait.h>

#include <chrono>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "cli_support.hpp"

namespace vibra::test {

/// Starts `vibra ARGS`, sends `signal` after `after` s, and returns its exit
/// code and the seconds from the signal to its end (a run that goes on for
/// 10 s is killed).
inline std::pair<int, double> stopped_after(const std::vector<std::string>& args, const ScratchDirectory& logs,
                                            int signal, double after) {
  const pid_t pid = spawn_vibra(args, logs / "out", logs / "err");
  std::this_thread::sleep_for(std::chrono::duration<double>(after));
  ::kill(pid, signal);
  const auto sent = std::chrono::steady_clock::now();
  int status = 0;
  for (int i = 0; i < 1000 && ::waitpid(pid, &status, WNOHANG) == 0; ++i)  // at most 10 s: a hang is killed
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - sent).count();
  if (seconds >= 10) ::kill(pid, SIGKILL), ::waitpid(pid, &status, 0);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -WTERMSIG(status), seconds};
}

}  // namespace vibra::test
