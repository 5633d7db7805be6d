// vibra render --live: the page and its companion folder written together, and what the page cannot take refused first.
#include <catch2/catch.hpp>
#include <filesystem>

#include "cli_support.hpp"

using vibra::test::check_refused;
using vibra::test::read_file;
using vibra::test::run_vibra;
using vibra::test::ScratchDirectory;

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
  CHECK_THAT(html, Catch::Contains(R"("scene":"pendulum","model":"pendulum","base":["Theta=45","size=640x360"])"));
  CHECK_THAT(html, Catch::Contains(R"(width="640" height="360")"));
  for (const char* file : {"vibra_live.js", "replay.js", "live.js", "live.css", "DejaVuSans.ttf", "DejaVuSans-Oblique.ttf"})
    CHECK(std::filesystem::file_size(dir.path / "explore_files" / file) > 1000);
  // Its own folder (its manifest proves it) is replaced by the next run.
  REQUIRE(run_vibra("render pendulum -o " + page + " --live").exit_code == 0);
  CHECK_THAT(read_file(page), Catch::Contains(R"("base":[])"));
}
