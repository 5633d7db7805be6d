// Resource bounds: peak memory does not grow with the length of a run. Each
// pair runs the real executable on a short and on a 100-500x longer run and
// compares the children's peak resident sizes (not a timed test: memory is
// steady where time is not).
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <string>
#include <vector>

#include "cli_support.hpp"

using vibra::test::ScratchDirectory;

namespace {

// Runs vibra with ARGS, output to /dev/null; returns its peak RSS in KiB.
long peak_kib(const std::vector<std::string>& args) {
  const pid_t pid = vibra::test::spawn_vibra(args, "/dev/null", "/dev/null");
  int status = 0;
  rusage usage{};
  wait4(pid, &status, 0, &usage);
  REQUIRE(WIFEXITED(status));
  REQUIRE(WEXITSTATUS(status) == 0);
  return usage.ru_maxrss;
}

// The long run may use a little more (allocator noise), never in proportion.
void check_flat(long short_kib, long long_kib) {
  INFO("short run " << short_kib << " KiB, long run " << long_kib << " KiB");
  CHECK(long_kib <= short_kib + short_kib / 10 + 4096);
}

}  // namespace

TEST_CASE("a moving-window render of 5e6 steps peaks at the memory of 1e4 steps", "[heavy][memory][render]") {
  ScratchDirectory dir;
  auto render = [&](const std::string& steps_per_period) {
    return peak_kib({"render", "undamped", "--set", "scheme=rk4", "--set", "steps_per_period=" + steps_per_period,
                     "--set", "periods=20", "--window", "4periods", "--size", "320x180", "--fps", "1", "--speed", "1",
                     "-q", "-o", dir / "f_%03d.png"});
  };
  const long short_run = render("500");  // 1e4 steps
  const long long_run = render("250000");  // 5e6 steps
  check_flat(short_run, long_run);
}

TEST_CASE("solve and ascii stream: 1e6 steps peak at the memory of 1e4", "[memory]") {
  for (const char* command : {"solve", "ascii"}) {
    INFO(command);
    auto run = [&](const std::string& periods) {
      return peak_kib({command, "undamped", "--set", "steps_per_period=100", "--set", "periods=" + periods});
    };
    check_flat(run("100"), run("10000"));
  }
}
