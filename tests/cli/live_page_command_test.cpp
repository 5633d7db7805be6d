// vibra render --live: the page and its companion folder written together, and what the page cannot take refused first.
#include <catch2/catch.hpp>
#include <algorithm>
#include <filesystem>

#include "cli_support.hpp"

using vibra::test::check_refused;
using vibra::test::read_file;
using vibra::test::run_vibra;
using vibra::test::ScratchDirectory;
using vibra::test::write_file;

TEST_CASE("render --live refuses a video output, a still's time and a bad value, writing nothing", "[cli][live]") {
  check_refused("render pendulum -o OUT.mp4 --live", "--live writes a page: give -o PAGE.html");
  check_refused("render pendulum -o OUT.html --live --at 3", "drop --at");
  check_refused("render pendulum --set alpha=-1 -o OUT.html --live", "the drag coefficient alpha must be >= 0");
}

TEST_CASE("render --live writes the page, its settings and its browser files, and replaces its own folder",
          "[cli][live]") {
  ScratchDirectory dir;
  const std::string page = dir / "explore.html";
  const auto r = run_vibra("render pendulum --size 640x360 --set Theta=45 -o " + page + " --live");
  if (r.exit_code == 2) {  // a vibra built without the browser build says how to get it
    CHECK_THAT(r.err, Catch::Contains("--live needs the browser build") && Catch::Contains("-DVIBRA_WEB=ON"));
    CHECK(dir.empty());
    return;
  }
  REQUIRE(r.exit_code == 0);
  const std::string html = read_file(page);
  CHECK_THAT(html, Catch::Contains(R"("scene":"pendulum","sceneText":"","name":"pendulum","model":"pendulum",)"
                                   R"("base":["Theta=45","size=640x360"])"));
  CHECK_THAT(html, Catch::Contains(R"(width="640" height="360")"));
  CHECK_THAT(html, Catch::Contains(R"("sceneKeys":[])"));  // compares nothing: no control beyond the model's keys
  for (const char* file : {"vibra_live.js", "replay.js", "live.js", "live.css", "DejaVuSans.ttf", "DejaVuSans-Oblique.ttf"})
    CHECK(std::filesystem::file_size(dir.path / "explore_files" / file) > 1000);
  // Its own folder (its manifest proves it) is replaced by the next run.
  REQUIRE(run_vibra("render pendulum -o " + page + " --live").exit_code == 0);
  CHECK_THAT(read_file(page), Catch::Contains(R"("base":[])"));
}

TEST_CASE("render --live takes a scene file into the page, and refuses one that reads another file, naming it",
          "[cli][live]") {
  ScratchDirectory dir;
  write_file(dir / "swing.toml", "# a pendulum of my own\nmodel = \"pendulum\"\nTheta = 70\nperiods = 4\n");
  const std::string page = dir / "swing.html";
  const auto r = run_vibra("render " + (dir / "swing.toml") + " --size 640x360 -o " + page + " --live");
  if (r.exit_code == 2 && r.err.find("--live needs the browser build") != std::string::npos) return;
  REQUIRE(r.exit_code == 0);
  // The file's text, for the page's WebAssembly to set the scene up from; its name for "Render this".
  const std::string html = read_file(page);
  CHECK_THAT(html, Catch::Contains(R"("sceneText":"# a pendulum of my own\nmodel = \"pendulum\"\nTheta = 70\nperiods = 4\n")"));
  CHECK_THAT(html, Catch::Contains(R"("name":"swing","model":"pendulum")"));
  CHECK_THAT(html, Catch::Contains(R"("initial":{"Theta":"70")"));

  // A road of heights from a file: the page has no files, so the run is refused before anything is written.
  std::string heights;
  for (int i = 0; i < 200; ++i) heights += i % 2 ? "0.01\n" : "0\n";
  write_file(dir / "road.txt", heights);
  write_file(dir / "road.toml", "model = \"bumpy-road\"\nroad = \"" + (dir / "road.txt") + "\"\ndx = 0.5\nT = 2\n");
  const std::string road_page = dir / "road.html";
  const auto refused = run_vibra("render " + (dir / "road.toml") + " -o " + road_page + " --live");
  CHECK(refused.exit_code == 2);
  CHECK_THAT(refused.err, Catch::StartsWith("vibra: error: --live cannot take '") &&
                              Catch::EndsWith("road.txt', the road profile (--set road), into the page, which reads no "
                                              "files: give that key a value that names no file (vibra solve bumpy-road "
                                              "--help lists them)\n"));
  CHECK(std::count(refused.err.begin(), refused.err.end(), '\n') == 1);
  CHECK(!std::filesystem::exists(road_page));
  CHECK(!std::filesystem::exists(dir.path / "road_files"));
}

TEST_CASE("render --live gives a comparison's values a control of the page, starting from them", "[cli][live]") {
  ScratchDirectory dir;
  const std::string page = dir / "compare.html";
  const auto r = run_vibra("render spring --set compare=dt=0.3,0.15 -o " + page + " --live");
  if (r.exit_code == 2 && r.err.find("--live needs the browser build") != std::string::npos) return;
  REQUIRE(r.exit_code == 0);
  const std::string html = read_file(page);
  CHECK_THAT(html, Catch::Contains(R"("compare":"dt=0.3,0.15")"));
  CHECK_THAT(html, Catch::Contains(R"("sceneKeys":[{"name":"compare","control":"text",)"));
}
