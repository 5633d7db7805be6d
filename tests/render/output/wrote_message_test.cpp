// Every command that writes a file says so on stderr in one line, as render
// does (a video after its progress summary), and every one of them takes
// --quiet to say nothing.
#include <catch2/catch.hpp>
#include <filesystem>

#include "cli_support.hpp"

using vibra::test::run_vibra;
using vibra::test::ScratchDirectory;

TEST_CASE("plot (picture, comparison, page), solve, analyze and render say what they wrote, and --quiet silences them", "[cli]") {
  ScratchDirectory dir;
  const std::pair<std::string, std::string> commands[] = {
      {"plot undamped --set periods=1 -o " + (dir / "u.png"), dir / "u.png"},
      {"plot undamped --set periods=1 --compare dt=0.1,0.05 -o " + (dir / "cmp.svg"), dir / "cmp.svg"},
      {"plot undamped --set periods=1 -o " + (dir / "u.html"), dir / "u.html"},
      {"solve undamped --set periods=1 -o " + (dir / "u.csv"), dir / "u.csv"},
      {"analyze convergence undamped --levels 3 -o " + (dir / "c.svg"), dir / "c.svg"},
      {"render --size 160x90 --set periods=0.25 --at 0.5 -o " + (dir / "still.png"), dir / "still.png"},
      {"render --size 160x90 --set periods=0.25 -o " + (dir / "clip.mp4"), dir / "clip.mp4"},
  };
  for (const auto& [command, file] : commands) {
    INFO("vibra " << command);
    const auto said = run_vibra(command);
    REQUIRE(said.exit_code == 0);
    // The last line, after a video's progress summary.
    const size_t last = said.err.rfind('\n', said.err.size() - 2);
    CHECK_THAT(said.err.substr(last == std::string::npos ? 0 : last + 1), Catch::StartsWith("vibra: wrote " + file));
    CHECK(std::count(said.err.begin(), said.err.end(), '\n') == (file.ends_with(".mp4") ? 2 : 1));
    std::filesystem::remove(file);
    for (const char* quiet : {" -q", " --quiet"}) {
      const auto silent = run_vibra(command + quiet);
      CHECK(silent.exit_code == 0);
      CHECK(silent.err.empty());
      CHECK(std::filesystem::exists(file));
    }
  }
}
