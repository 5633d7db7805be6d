// Replays the fuzz corpus and every input a fuzzer ever found a bug with
// (tests/fuzz/regressions/TARGET/WHAT-IT-FOUND) through the fuzz entries, in
// the normal suite and under the sanitizers: a fixed bug stays fixed.
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "fuzz/fuzz_inputs.hpp"

namespace fs = std::filesystem;

namespace {

template <class Entry>
int replay(const std::string& target, Entry entry) {
  int inputs = 0;
  for (const char* kind : {"corpus", "regressions"}) {
    const fs::path dir = fs::path(VIBRA_FUZZ_DIR) / kind / target;
    if (!fs::is_directory(dir)) continue;
    for (const auto& file : fs::directory_iterator(dir)) {
      std::ifstream in(file.path(), std::ios::binary);
      std::stringstream text;
      text << in.rdbuf();
      INFO(file.path().string());
      REQUIRE_NOTHROW(entry(text.str()));
      ++inputs;
    }
  }
  return inputs;
}

}  // namespace

TEST_CASE("fuzz inputs replay cleanly: scene files", "[fuzz]") {
  CHECK(replay("scene_file", vibra::fuzz::scene_file) >= 5);
}

TEST_CASE("fuzz inputs replay cleanly: storyboards", "[fuzz]") {
  CHECK(replay("storyboard", vibra::fuzz::storyboard) >= 8);  // with crowded notes (issue 42)
}

TEST_CASE("fuzz inputs replay cleanly: --set assignments", "[fuzz]") {
  CHECK(replay("set_assignments", vibra::fuzz::set_assignments) >= 6);
}

TEST_CASE("fuzz inputs replay cleanly: expressions", "[fuzz]") {
  CHECK(replay("expression", vibra::fuzz::expression) >= 5);
}

TEST_CASE("fuzz inputs replay cleanly: command lines", "[fuzz]") {
  CHECK(replay("command_line", vibra::fuzz::command_line) >= 17);  // with the classes of issue 42
}

TEST_CASE("fuzz inputs replay cleanly: formulas", "[fuzz]") {
  CHECK(replay("formula", vibra::fuzz::formula) >= 8);
}
