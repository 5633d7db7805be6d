// Every byte on standard output is checked (docs/reliability.md, "Standard
// output"): a full disk or a closed descriptor is one line on stderr and exit
// code 2, whichever command wrote; a reader that goes away is a pipeline's
// normal end: exit code 0, nothing on stderr.
#include <algorithm>
#include <catch2/catch.hpp>
#include <string>

#include "cli_support.hpp"

using vibra::test::check_refusal;
using vibra::test::run_vibra;

namespace {
/// `vibra ARGS REDIRECT` fails with one line naming standard output and `reason`.
void check_write_refused(const std::string& args, const std::string& redirect, const std::string& reason) {
  INFO("vibra " << args << " " << redirect);
  const auto r = run_vibra(args + " " + redirect);
  check_refusal(r, reason);
  CHECK_THAT(r.err, Catch::StartsWith("vibra: error: writing standard output: "));
}

// Each command's way of writing: solve's CSV writer, ascii's lines, analyze's
// tables and CSV, solve's own help, CLI11's help (--help at the top and on a
// subcommand), plot's help.
const char* const kWriters[] = {
    "solve pendulum",
    "solve pendulum -o -",
    "ascii undamped --set T=20",
    "analyze energy",
    "analyze energy --csv",
    "analyze empirical undamped --csv",
    "solve --help",
    "--help",
    "render --help",
    "plot --help",
};
}  // namespace

TEST_CASE("a full disk behind standard output is one line and exit code 2, for every command", "[stdout][cli]") {
  for (const char* args : kWriters) check_write_refused(args, "> /dev/full", "No space left on device");
}

TEST_CASE("a closed standard output is one line and exit code 2", "[stdout][cli]") {
  for (const char* args : kWriters) check_write_refused(args, ">&-", "Bad file descriptor");
  check_write_refused("render --size 320x180 --set periods=0.5 -q -o - --format y4m", ">&-", "Bad file descriptor");
}

TEST_CASE("a command that writes nothing to a closed standard output succeeds", "[stdout][cli]") {
  vibra::test::ScratchDirectory dir;
  const auto r = run_vibra("solve undamped -q -o " + (dir / "u.csv") + " >&-");
  CHECK(r.exit_code == 0);
  CHECK(r.err.empty());
}

TEST_CASE("a reader that goes away after 10 bytes ends every stream quietly", "[stdout][cli]") {
  const std::vector<std::vector<std::string>> streams = {
      {"solve", "undamped", "--set", "T=1e5"},
      {"ascii", "undamped", "--set", "T=inf"},
      {"render", "--size", "320x180", "--set", "periods=200", "-q", "-o", "-", "--format", "y4m"},
  };
  for (const auto& args : streams) {
    INFO(args[0]);
    const auto r = vibra::test::read_then_close(args, 10);
    CHECK(r.exit_code == 0);
    CHECK(r.err.empty());
  }
}
