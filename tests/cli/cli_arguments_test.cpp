// Malformed command lines, for every command and every analyze experiment:
// an unknown option, an option without its value and an unexpected positional
// argument are each refused as all bad input is (check_refused: exit code 2,
// exactly one line on stderr naming the problem, nothing written).
#include <catch2/catch.hpp>
#include <string>

#include "cli_support.hpp"

namespace {
struct Command {
  const char* name;    ///< the command (and experiment) as typed
  const char* valid;   ///< a command line that runs: OUT is a path in a scratch directory, SEGS one holding segments
  const char* option;  ///< an option of this command that takes a value (none for analyze itself)
};

// Each command's valid line is kept cheap: the refusal must come before any work.
const Command kCommands[] = {
    {"solve", "solve undamped -o OUT.csv", "--every"},
    {"render", "render pendulum --size 320x180 -o OUT.mp4", "--fps"},
    {"ascii", "ascii undamped --set T=1 --width 20", "--width"},
    {"plot", "plot undamped -o OUT.png", "--panels"},
    {"analyze", "analyze frequency -o OUT.png", nullptr},
    {"analyze amplitude", "analyze amplitude -o OUT.png", "--periods"},
    {"analyze bounces", "analyze bounces --csv", "--set"},
    {"analyze convergence", "analyze convergence undamped -o OUT.png", "--levels"},
    {"analyze empirical", "analyze empirical undamped -o OUT.png", "--dt"},
    {"analyze energy", "analyze energy -o OUT.png", "--schemes"},
    {"analyze frequency", "analyze frequency -o OUT.png", "--w"},
    {"analyze orbit", "analyze orbit -o OUT.png", "--orbits"},
    {"analyze period", "analyze period undamped -o OUT.png", "--set"},
    {"analyze resonance", "analyze resonance -o OUT.png", "--beta"},
    // concat takes any number of parts: an extra one is a file that is no segment of the render.
    {"chapter", "chapter --only ex1.19 -o OUT", "--only"},
    {"concat", "concat SEGS/p.seg-0-of-2.mp4 SEGS/p.seg-1-of-2.mp4 -o OUT.mp4", "--output"},
};

/// The segments of a tiny render, for concat's valid line.
const vibra::test::ScratchDirectory& segments() {
  static const vibra::test::ScratchDirectory dir = [] {
    vibra::test::ScratchDirectory d;
    for (const char* k : {"0/2", "1/2"})
      REQUIRE(vibra::test::run_vibra(std::string("render --size 160x90 --set periods=0.2 -q --segment ") + k + " -o " +
                                     (d / "p.mp4"))
                  .exit_code == 0);
    return d;
  }();
  return dir;
}
}  // namespace

TEST_CASE("every command refuses an unknown option, a missing value and an extra argument with one line and exit code 2",
          "[cli]") {
  for (const Command& c : kCommands) {
    INFO("command: " << c.name);
    std::string valid = c.valid;
    for (auto at = valid.find("SEGS"); at != std::string::npos; at = valid.find("SEGS")) valid.replace(at, 4, segments().path);
    // After the command's name (and the experiment's): an option nobody has.
    const std::string head = valid.substr(0, valid.find(' ', std::string(c.name).size()));
    const std::string rest = valid.substr(head.size());
    vibra::test::check_refused(head + " --no-such-option" + rest, "--no-such-option");
    // The value-taking option last, with nothing after it.
    if (c.option) vibra::test::check_refused(valid + " " + c.option, c.option);
    // A positional argument the command does not take, named.
    vibra::test::check_refused(valid + " extra", "extra");
  }
}
