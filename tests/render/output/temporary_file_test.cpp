// Temporaries of killed runs: removed when they are this host's and their
// process is gone; left alone when another host (sharing the disk) made them.
#include <sys/wait.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <fstream>
#include <string>

#include "cli_support.hpp"
#include "render/output/temporary_file.hpp"

using vibra::render::TemporaryFile;
using vibra::test::ScratchDirectory;

namespace {
std::string this_host() {
  char name[256] = {};
  REQUIRE(gethostname(name, sizeof name - 1) == 0);
  std::string host(name);
  for (char& c : host)
    if (c == '-' || c == '/') c = '_';
  return host;
}

/// The PID of a process that has ended.
pid_t ended_process() {
  const pid_t pid = fork();
  if (pid == 0) _exit(0);
  waitpid(pid, nullptr, 0);
  return pid;
}
}  // namespace

TEST_CASE("stale temporaries: this host's dead runs are removed, other hosts' and live ones stay", "[output]") {
  ScratchDirectory dir;
  const std::string dead = ".a.mp4.vibra-tmp-" + this_host() + "-" + std::to_string(ended_process());
  const std::string live = ".b.mp4.vibra-tmp-" + this_host() + "-" + std::to_string(getpid());
  const std::string other_host = ".c.mp4.vibra-tmp-node_17-" + std::to_string(ended_process());
  for (const auto& name : {dead, live, other_host}) std::ofstream(dir / name) << "partial";
  const auto stale = TemporaryFile::stale_in(dir.path);
  REQUIRE(stale.size() == 1);
  CHECK(stale.front().filename() == dead);

  TemporaryFile file(dir / "out.mp4");  // the first in a directory clears what is stale
  CHECK(file.path().filename().string() == ".out.mp4.vibra-tmp-" + this_host() + "-" + std::to_string(getpid()));
  CHECK_FALSE(std::filesystem::exists(dir / dead));
  CHECK(std::filesystem::exists(dir / live));
  CHECK(std::filesystem::exists(dir / other_host));
}
