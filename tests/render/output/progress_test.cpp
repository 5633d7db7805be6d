// A render's progress on stderr: the bar a terminal sees (a pseudo-terminal here), the closing line, and silence when quiet.
#include <catch2/catch.hpp>
#include <fcntl.h>
#include <pty.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <functional>
#include <string>
#include <thread>

#include "render/output/progress.hpp"

namespace {
/// What `run` writes to stderr while stderr is a pseudo-terminal.
std::string on_a_terminal(const std::function<void()>& run) {
  int master = -1, slave = -1;
  REQUIRE(openpty(&master, &slave, nullptr, nullptr, nullptr) == 0);
  std::fflush(stderr);
  const int saved = dup(STDERR_FILENO);
  REQUIRE(dup2(slave, STDERR_FILENO) == STDERR_FILENO);
  run();
  std::fflush(stderr);
  dup2(saved, STDERR_FILENO);
  close(saved), close(slave);
  fcntl(master, F_SETFL, O_NONBLOCK);
  std::string out;
  char buf[4096];
  for (ssize_t n; (n = read(master, buf, sizeof buf)) > 0;) out.append(buf, size_t(n));
  close(master);
  return out;
}

void wait_past_the_terminal_interval() { std::this_thread::sleep_for(std::chrono::milliseconds(120)); }
}  // namespace

TEST_CASE("a terminal sees a bar of 30 cells filled in proportion, then the closing line over it", "[progress]") {
  const std::string out = on_a_terminal([] {
    vibra::render::Progress progress("render", 10, false);
    progress.update(1);  // within 0.1 s of the start: not drawn
    wait_past_the_terminal_interval();
    progress.update(5);
    progress.update(6);  // within 0.1 s of the last bar: not drawn
    progress.finish(10);
  });
  INFO(out);
  CHECK(out.find("\rrender [###############...............] 5/10 frames  ") != std::string::npos);
  CHECK(out.find(" 1/10 frames") == std::string::npos);
  CHECK(out.find(" 6/10 frames") == std::string::npos);
  CHECK(out.find("\r\033[Krender: 10 frames in ") != std::string::npos);
  CHECK(out.find(" frames/s)") != std::string::npos);
}

TEST_CASE("a quiet run writes no progress at all", "[progress]") {
  const std::string out = on_a_terminal([] {
    vibra::render::Progress progress("render", 10, true);
    wait_past_the_terminal_interval();
    progress.update(5);
    progress.finish(10);
  });
  CHECK(out.empty());
}
