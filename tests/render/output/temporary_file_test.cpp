// Temporaries of killed runs: removed when they are this host's and their
// process is gone; left alone when another host (sharing the disk) made them.
#include <sys/wait.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <algorithm>
#include <csignal>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "cli_support.hpp"
#include "core/stop_flag.hpp"
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

TEST_CASE("a stop asked for before the finished output moves: the earlier output stays whole, nothing new is kept", "[output]") {
  // Frames replace a set of files, a page its folder: a run stopped at the
  // last moment keeps neither a mixed set nor its temporary.
  const auto read = [](const std::filesystem::path& p) {
    std::ifstream in(p);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  const auto names = [](const std::filesystem::path& dir) {
    std::vector<std::string> out;
    for (const auto& e : std::filesystem::directory_iterator(dir)) out.push_back(e.path().filename().string());
    std::sort(out.begin(), out.end());
    return out;
  };
  ScratchDirectory dir;
  std::ofstream(dir / "frame_0001.png") << "earlier 1";
  std::ofstream(dir / "frame_0002.png") << "earlier 2";
  std::filesystem::create_directory(dir / "page_files");
  std::ofstream(dir.path / "page_files" / "run.csv") << "earlier csv";
  {
    vibra::render::TemporaryDirectory frames(dir.path, "frames");
    for (const char* name : {"frame_0001.png", "frame_0002.png"}) std::ofstream(frames.path() / name) << "new";
    vibra::render::TemporaryDirectory page(dir.path, "page_files");
    std::ofstream(page.path() / "run.csv") << "new csv";
    vibra::record_stop_signal(SIGINT);
    const auto moved = [&] { frames.move_files_into_location(); };
    CHECK_THROWS_AS(moved(), vibra::Interrupted);
    vibra::record_stop_signal(SIGINT);
    const auto replaced = [&] { page.replace(dir / "page_files"); };
    CHECK_THROWS_AS(replaced(), vibra::Interrupted);
    vibra::take_stop_signal();
  }
  CHECK(read(dir / "frame_0001.png") == "earlier 1");
  CHECK(read(dir / "frame_0002.png") == "earlier 2");
  CHECK(read(dir.path / "page_files" / "run.csv") == "earlier csv");
  CHECK(names(dir.path) == std::vector<std::string>{"frame_0001.png", "frame_0002.png", "page_files"});
  CHECK(names(dir.path / "page_files") == std::vector<std::string>{"run.csv"});
}
